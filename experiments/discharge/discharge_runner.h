#pragma once
// The `demcal experiment discharge` runner (discharge_runner.cc): replicates of the file's run, their
// tables and pictures, DIR/result.json; a process exit code (outputs/exit_codes.h).
#include <ostream>

#include "experiments/common/experiment_runner.h"

namespace demcal::workflow {

int RunDischargeExperiment(const ExperimentFile& file, const ExperimentContext& context,
                     std::ostream& log);

}  // namespace demcal::workflow
