#pragma once
// `demcal experiment`: the command-line front of experiments/common/run_experiment.h (argv, help, progress on stderr); the work
// is done by the workflow layer.
#include "apps/command.h"

namespace demcal::apps {

Command AddExperimentCommand(CLI::App& parent);

}  // namespace demcal::apps
