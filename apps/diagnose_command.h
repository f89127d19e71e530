#pragma once
// `demcal diagnose`: the discrepancy workflow (diagnose/run_diagnose.h, docs/diagnose.md).
#include "apps/command.h"

namespace demcal::apps {

Command AddDiagnoseCommand(CLI::App& parent);

}  // namespace demcal::apps
