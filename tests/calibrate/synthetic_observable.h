#pragma once
// A cheap stand-in for a virtual experiment in calibration tests: a probe whose "angle" =
// a + b·μ_r + c·μ_s read from the model's pair 0–0, plus seeded noise that depends only on the
// seed (as packing noise does under common random numbers). Counts its runs; can fail above a
// rolling friction (status "not_settled", as a heap that never settles), or scatter more above
// one (a rough heap).
#include <atomic>
#include <cmath>

#include "calibrate/experiment_probe.h"
#include "core/math/random.h"

namespace demcal::calibrate::testing {

class SyntheticAngle final : public ExperimentProbe {
 public:
  double base = 15, per_rolling = 60, per_sliding = 0, noise_deg = 0.5;
  double fail_above_rolling = 1e9;
  double noisy_above_rolling = 1e9, noisy_deg = 0;  // above: noise noisy_deg (a rough heap)
  mutable std::atomic<int> runs{0};

  std::string Kind() const override { return "synthetic"; }
  std::vector<std::string> Observables() const override { return {"angle_deg"}; }
  ProbeOutcome Run(const core::Scene& model, uint64_t seed) const override {
    ++runs;
    const core::PairParameters& p = model.pair_parameters[0];
    if (p.rolling_friction > fail_above_rolling) return {"not_settled", {}, 0};
    core::Rng rng(seed);
    const double u1 = 1.0 - rng.Uniform(), u2 = rng.Uniform();  // Box–Muller normal
    const double z = std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * 3.141592653589793 * u2);
    const double sd = p.rolling_friction > noisy_above_rolling ? noisy_deg : noise_deg;
    const double angle =
        base + per_rolling * p.rolling_friction + per_sliding * p.sliding_friction + sd * z;
    return {"ok", {{"angle_deg", angle}}, 0};
  }
};

inline core::Scene OneMaterialModel() {
  core::Scene s;
  s.materials = {{"BP", 2.5e8, 0.25, 780}};
  s.pair_parameters.assign(1, core::PairParameters{});
  return s;
}

}  // namespace demcal::calibrate::testing
