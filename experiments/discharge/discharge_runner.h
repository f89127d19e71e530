#pragma once
// The `demcal experiment discharge` runner (discharge_runner.cc): replicates of the file's run,
// their tables and pictures, DIR/result.json written from the returned DischargeResult.
#include <ostream>
#include <vector>

#include "experiments/common/experiment_runner.h"
#include "experiments/discharge/discharge_experiment.h"

namespace demcal::workflow {

struct DischargeResult {
  ExperimentStatus status = ExperimentStatus::kInvalidInput;
  objectives::DischargeSettings settings;  // the parsed section (hopper, fill, feed)
  int replicates_ok = 0;
  // Mean ± standard error over the replicates that are ok.
  objectives::Summary discharge_time_s, mass_flow_kg_s, bulk_density_kg_m3;
  std::vector<objectives::DischargeRun> runs;  // in replicate order
  // {"discharge_time_s", "mass_flow_kg_s", "bulk_density_kg_m3"}
  std::vector<NamedEstimate> Values() const {
    return {{"discharge_time_s", discharge_time_s},
            {"mass_flow_kg_s", mass_flow_kg_s},
            {"bulk_density_kg_m3", bulk_density_kg_m3}};
  }
};

DischargeResult RunDischargeExperiment(const ExperimentFile& file,
                                       const ExperimentContext& context, std::ostream& log);

}  // namespace demcal::workflow
