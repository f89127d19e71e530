#pragma once
// `demcal export liggghts EXPERIMENT.json --out DIR`: an experiment as a runnable
// LIGGGHTS-PUBLIC 3.8 deck (workflow/export/run_export.h; docs/export.md).
#include "apps/command.h"

namespace demcal::apps {

Command AddExportCommand(CLI::App& parent);

}  // namespace demcal::apps
