#include "experiments/discharge/discharge_probe.h"

namespace demcal::calibrate {

std::vector<std::string> DischargeProbe::Observables() const {
  return {"discharge_time_s", "mass_flow_kg_s", "bulk_density_kg_m3"};
}

ProbeOutcome DischargeProbe::Run(const core::Scene& model, uint64_t seed) const {
  const objectives::DischargeRun run = objectives::RunDischarge(model, settings_, seed, {});
  ProbeOutcome outcome;
  outcome.status = run.ok() ? "ok" : run.status == "ok" ? "no_metrics" : run.status;
  outcome.wall_time_s = run.wall_time_s;
  if (!run.ok()) return outcome;
  outcome.values = {{"discharge_time_s", run.metrics.discharge_time_s},
                    {"mass_flow_kg_s", run.metrics.mass_flow_kg_s}};
  if (run.bulk_density_kg_m3 > 0) outcome.values["bulk_density_kg_m3"] = run.bulk_density_kg_m3;
  return outcome;
}

}  // namespace demcal::calibrate
