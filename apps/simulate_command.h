#pragma once
// `demcal simulate`: the command-line front of workflow/simulation/simulate.h (argv, help, progress on stderr); the work
// is done by the workflow layer.
#include "apps/command.h"

namespace demcal::apps {

Command AddSimulateCommand(CLI::App& parent);

}  // namespace demcal::apps
