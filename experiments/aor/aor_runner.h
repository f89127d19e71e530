#pragma once
// The `demcal experiment aor` runner (aor_runner.cc): replicates of the file's run, their
// tables and pictures, DIR/result.json written from the returned AorResult.
#include <ostream>
#include <string>
#include <vector>

#include "experiments/aor/aor_experiment.h"
#include "experiments/common/experiment_runner.h"

namespace demcal::workflow {

struct AorResult {
  ExperimentStatus status = ExperimentStatus::kInvalidInput;
  std::string heap;                   // "slot" or "conical"
  int replicates_ok = 0;
  objectives::Summary angle_deg;      // mean, std and sem over the replicates that gave an angle
  std::vector<objectives::AorRun> runs;  // in replicate order
  // {"angle_deg"}
  std::vector<NamedEstimate> Values() const { return {{"angle_deg", angle_deg}}; }
};

AorResult RunAorExperiment(const ExperimentFile& file, const ExperimentContext& context,
                           std::ostream& log);

}  // namespace demcal::workflow
