#include "calibrate/aor_observable.h"

namespace demcal::calibrate {

ReplicateOutcome AorObservable::Run(const core::Scene& model, uint64_t seed) const {
  const objectives::AorRun run = objectives::RunAor(model, settings_, seed, {});
  ReplicateOutcome outcome;
  outcome.status = run.Status();
  outcome.value = run.ok() ? run.angle.angle_deg : 0.0;
  outcome.wall_time_s = run.wall_time_s;
  return outcome;
}

}  // namespace demcal::calibrate
