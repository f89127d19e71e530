#pragma once
// `demcal reproduce`: the command-line front of workflow/reproduce/run_reproduce.h (argv, help,
// progress on stderr); the work is done by the workflow layer.
#include "apps/command.h"

namespace demcal::apps {

Command AddReproduceCommand(CLI::App& parent);

}  // namespace demcal::apps
