// `demcal experiment discharge` (in progress).
#include "apps/exit_codes.h"
#include "apps/experiment_runner.h"

namespace demcal::apps {

int RunDischargeExperiment(const ExperimentFile& file, const ExperimentContext&, std::ostream& log) {
  log << "error: " << file.source << ": the discharge experiment is not available yet\n";
  return kExitInvalidInput;
}

}  // namespace demcal::apps
