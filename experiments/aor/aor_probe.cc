#include "experiments/aor/aor_probe.h"

#include "objectives/metrics/heap_crest.h"

namespace demcal::calibrate {

std::vector<std::string> AorProbe::Observables() const {
  return {"angle_deg", "heap_height_m", "crest_drop_m"};
}

ProbeOutcome AorProbe::Run(const core::Scene& model, uint64_t seed) const {
  const objectives::AorRun run = objectives::RunAor(model, settings_, seed, {});
  ProbeOutcome outcome;
  outcome.status = run.Status();
  outcome.wall_time_s = run.wall_time_s;
  if (!run.ok()) return outcome;
  outcome.values = {{"angle_deg", run.angle.angle_deg},
                    {"heap_height_m", run.angle.heap_height_m},
                    {"crest_drop_m", objectives::CrestDrop(run.angle, run.angle_options.base_z_m)}};
  return outcome;
}

}  // namespace demcal::calibrate
