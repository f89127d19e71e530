#pragma once
// `demcal calibrate`: the command-line front of workflow/calibration/run_study.h (argv, help, progress on stderr); the work
// is done by the workflow layer.
#include "apps/command.h"

namespace demcal::apps {

Command AddCalibrateCommand(CLI::App& parent);

}  // namespace demcal::apps
