// Sensitivity refinement on a linear stand-in (no DEM) whose candidates draw independent noise,
// so the optimiser's finite differences are noisy: a calibration that matches at its start gets
// σ = +∞ for want of points, and a few refinement stencils around the best give finite σ close
// to the analytic ones, σ = sqrt(diag((JᵀJ)⁻¹)) with J the exact standardised sensitivities.
#include <catch2/catch.hpp>
#include <cmath>

#include "analytic_models.h"
#include "calibrate/calibration.h"
#include "calibrate/sensitivity_refinement.h"

using namespace demcal::calibrate;
using demcal::calibrate::testing::LinearTargets;

namespace {

ParameterSpace Space() {
  ParameterSpace space;
  space.parameters.push_back({"mu_s", PairProperty::kSlidingFriction, 0, 0, 0.1, 0.6, 0.4});
  space.parameters.push_back({"mu_r", PairProperty::kRollingFriction, 0, 0, 0.02, 0.3, 0.15});
  return space;
}

// angle = 15 + 10 mu_s + 60 mu_r (u 1 deg, sem 0.5 deg); time = 0.2 + 0.5 mu_s + 0.3 mu_r
// (u 0.012 s, sem 0.006 s): sensitivities of the size the DEM rig twin measured near its truth.
LinearTargets Model() {
  LinearTargets m;
  m.offset = {15, 0.2};
  m.slope = {{10, 60}, {0.5, 0.3}};
  m.sem = {0.5, 0.006};
  m.independent_noise = true;
  return m;
}

// Measurements made at the start itself, so the first candidate matches within noise.
std::vector<Target> AtStart(const LinearTargets& m) {
  const std::vector<double> start{0.4, 0.15};
  return {{"angle", "angle_deg", m.Exact(0, start), 1.0, "synthetic"},
          {"time", "discharge_time_s", m.Exact(1, start), 0.012, "synthetic"}};
}

CalibrationSummary Run(int rounds, uint64_t seed) {
  LinearTargets m = Model();
  m.seed = seed;
  CalibrationOptions o;
  o.optimiser = "ceres";
  o.optimiser_options.max_evaluations = 30;
  o.sensitivity_rounds = rounds;
  return Calibrate(m, Space(), AtStart(m), o);
}

}  // namespace

TEST_CASE("refinement stencils double the finite-difference step and stay in the bounds",
          "[unit][calibrate]") {
  CHECK(FiniteDifferenceStep(0.1) == Approx(4 * 0.1 / std::sqrt(12.0)));
  CHECK(FiniteDifferenceStep(0) == 0.01);
  CHECK(FiniteDifferenceStep(10) == 0.25);
  const auto r0 = RefinementStencil({0.5, 0.5}, 0.05, 0);
  REQUIRE(r0.size() == 4);
  CHECK(r0[0][0] == Approx(0.5 - 2 * FiniteDifferenceStep(0.05)));
  CHECK(RefinementStencil({0.5, 0.95}, 0.05, 0).size() == 3);  // 0.95 + 0.115 leaves the cube
  CHECK(RefinementStencil({0.5, 0.5}, 0.05, 3)[0][0] == Approx(0.25));  // capped at 0.25
}

TEST_CASE("a match at the start with noisy sensitivities is refined to a finite sigma",
          "[unit][calibrate]") {
  // Exact standardised J per unit cube: slope × range / (u·sqrt(1 + noise²)), noise = sem/u = 0.5.
  const double w = 1 / std::sqrt(1 + 0.25);
  Eigen::Matrix2d j;
  j << 10 * 0.5 / 1.0 * w, 60 * 0.28 / 1.0 * w, 0.5 * 0.5 / 0.012 * w, 0.3 * 0.28 / 0.012 * w;
  const Eigen::Matrix2d cov = (j.transpose() * j).inverse();
  const double sigma_true[2] = {std::sqrt(cov(0, 0)) * 0.5, std::sqrt(cov(1, 1)) * 0.28};
  int infinite_without = 0;
  for (uint64_t seed = 1; seed <= 5; ++seed) {
    INFO("seed " << seed);
    const CalibrationSummary plain = Run(0, seed);
    REQUIRE(plain.termination == Termination::kWithinNoise);
    infinite_without += !std::isfinite(plain.estimates[0].sigma) || !std::isfinite(plain.estimates[1].sigma);
    const CalibrationSummary refined = Run(2, seed);
    REQUIRE(refined.termination == Termination::kWithinNoise);
    CHECK(refined.candidates[refined.best].parameters == plain.candidates[plain.best].parameters);
    for (int k = 0; k < 2; ++k) {
      INFO("parameter " << k << " sigma " << refined.estimates[k].sigma << " analytic " << sigma_true[k]);
      REQUIRE(std::isfinite(refined.estimates[k].sigma));
      CHECK(refined.estimates[k].sigma > sigma_true[k] / 2);
      CHECK(refined.estimates[k].sigma < sigma_true[k] * 2);
    }
    if (!std::isfinite(plain.estimates[0].sigma) || !std::isfinite(plain.estimates[1].sigma))
      CHECK(refined.refinement_points > 0);
  }
  CHECK(infinite_without >= 2);  // the scenario needs the refinement in most draws
}

TEST_CASE("refinement re-runs its stencil at the most replicates, lowering the sensitivities' noise",
          "[unit][calibrate]") {
  // Noisier runs (sem 0.9 u) and sensitivities half those of the case above: stencil points at
  // three replicates leave the sensitivities' noise floor above J's second singular value in
  // most draws; the same points at 4 × 3 replicates (max_replicate_factor) resolve it. (Noise
  // stays below kMatchNoise, so no candidate is sharpened: the replicates added are the
  // refinement's alone.)
  constexpr double kSlopeScale = 0.5;
  auto run = [](uint64_t seed, bool replicable) {
    LinearTargets m = Model();
    m.sem = {0.9, 0.0108};
    for (auto& row : m.slope)
      for (double& s : row) s *= kSlopeScale;
    m.seed = seed;
    m.replicable = replicable;
    CalibrationOptions o;
    o.optimiser = "ceres";
    o.optimiser_options.max_evaluations = 30;
    return Calibrate(m, Space(), AtStart(m), o);
  };
  const double w = kSlopeScale / std::sqrt(1 + 0.81);
  Eigen::Matrix2d j;
  j << 10 * 0.5 * w, 60 * 0.28 * w, 0.5 * 0.5 / 0.012 * w, 0.3 * 0.28 / 0.012 * w;
  const Eigen::Matrix2d cov = (j.transpose() * j).inverse();
  const double sigma_true[2] = {std::sqrt(cov(0, 0)) * 0.5, std::sqrt(cov(1, 1)) * 0.28};
  int infinite_plain = 0, infinite_deep = 0;
  for (uint64_t seed = 1; seed <= 5; ++seed) {
    INFO("seed " << seed);
    const CalibrationSummary plain = run(seed, false), deep = run(seed, true);
    REQUIRE(deep.termination == Termination::kWithinNoise);
    CHECK(deep.candidates[deep.best].parameters == plain.candidates[plain.best].parameters);
    infinite_plain += !std::isfinite(plain.estimates[0].sigma) || !std::isfinite(plain.estimates[1].sigma);
    infinite_deep += !std::isfinite(deep.estimates[0].sigma) || !std::isfinite(deep.estimates[1].sigma);
    REQUIRE(deep.refinement_points > 0);
    const size_t first_refined = deep.candidates.size() - static_cast<size_t>(deep.refinement_points);
    for (size_t k = 0; k < deep.candidates.size(); ++k)  // 4 × 3 replicates: stencil points only
      CHECK(deep.candidates[k].replicates_added == (k >= first_refined ? 9 : 0));
    for (int k = 0; k < 2; ++k) {
      if (!std::isfinite(deep.estimates[k].sigma)) continue;
      INFO("parameter " << k << " sigma " << deep.estimates[k].sigma << " analytic " << sigma_true[k]);
      CHECK(deep.estimates[k].sigma > sigma_true[k] / 2);
      CHECK(deep.estimates[k].sigma < sigma_true[k] * 2);
    }
  }
  CHECK(infinite_plain >= 3);
  CHECK(infinite_deep == 0);
}
