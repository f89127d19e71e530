#pragma once
// The angle of repose (objectives/aor/aor_experiment.h) as a calibration observable: one poured,
// settled and measured heap per replicate; value = mean of the flank angles (deg).
//
//   AorObservable angle(settings);   // settings parsed from the experiment's "aor" section
//   ReplicateOutcome o = angle.Run(model_at_fidelity, seed);
#include "calibrate/observable.h"
#include "objectives/aor/aor_experiment.h"

namespace demcal::calibrate {

class AorObservable final : public Observable {
 public:
  explicit AorObservable(objectives::AorSettings settings) : settings_(std::move(settings)) {}
  std::string Name() const override { return "angle_deg"; }
  std::string Unit() const override { return "deg"; }
  ReplicateOutcome Run(const core::Scene& model, uint64_t seed) const override;

 private:
  objectives::AorSettings settings_;
};

}  // namespace demcal::calibrate
