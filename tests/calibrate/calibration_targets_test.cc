// The multi-target driver on a linear stand-in (no DEM): an angle that sees mu_s and mu_r in
// one combination (a valley), a second target that separates them, the reported σ against the
// spread of recoveries over noise seeds, the target that would lift the valley, failed samples.
#include <catch2/catch.hpp>
#include <cmath>

#include "analytic_models.h"
#include "calibrate/calibration.h"
#include "calibrate/parameter_covariance.h"
#include "calibrate/target_gain.h"

using namespace demcal::calibrate;
using demcal::calibrate::testing::LinearTargets;
using demcal::calibrate::testing::Normal;

namespace {

const std::vector<double> kTruth{0.5, 0.3};  // mu_s, mu_r

ParameterSpace Space() {
  ParameterSpace space;
  space.parameters.push_back({"mu_s", PairProperty::kSlidingFriction, 0, 0, 0.1, 1.0, 0.9});
  space.parameters.push_back({"mu_r", PairProperty::kRollingFriction, 0, 0, 0.02, 0.9, 0.8});
  return space;
}

// angle = 15 + 20 mu_s + 60 mu_r (u = 0.5 deg, sem 0.1); "flow" = 10 + 8 mu_s − 3 mu_r
// (u = 0.1, sem 0.02).
LinearTargets Model(uint64_t seed, size_t targets) {
  LinearTargets m;
  m.offset = {15, 10};
  m.slope = {{20, 60}, {8, -3}};
  m.sem = {0.1, 0.02};
  m.offset.resize(targets), m.slope.resize(targets), m.sem.resize(targets);
  m.seed = seed;
  return m;
}

// Measured values: the truth plus measurement noise of seed `seed`.
std::vector<Target> Measured(uint64_t seed, size_t targets) {
  const LinearTargets m = Model(0, 2);
  const double u[2] = {0.5, 0.1};
  std::vector<Target> out;
  for (size_t k = 0; k < targets; ++k)
    out.push_back({k ? "flow" : "angle", k ? "mass_flow_kg_s" : "angle_deg",
                   m.Exact(k, kTruth) + u[k] * Normal(seed + 1000, static_cast<int>(k)), u[k],
                   "twin"});
  return out;
}

CalibrationOptions Ceres() {
  CalibrationOptions o;
  o.optimiser = "ceres";
  o.optimiser_options.max_evaluations = 40;
  return o;
}

}  // namespace

TEST_CASE(
    "one angle for mu_s and mu_r: matched, not identifiable, the valley named, and the "
    "target that lifts it",
    "[unit][calibrate]") {
  LinearTargets model = Model(1, 1);
  const CalibrationSummary s = Calibrate(model, Space(), Measured(1, 1), Ceres());
  INFO(s.BriefReport(Space()));
  REQUIRE(s.best >= 0);
  CHECK(s.termination == Termination::kWithinNoise);
  REQUIRE(s.estimates.size() == 2);
  for (const ParameterEstimate& e : s.estimates) {
    CHECK_FALSE(e.identifiable);
    CHECK(std::isinf(e.sigma));  // no fake finite σ
  }
  REQUIRE(s.identifiability.undetermined.size() == 1);
  CHECK(s.identifiability.undetermined[0].description.find("mu_s and mu_r trade off") !=
        std::string::npos);
  // Along the named direction the angle does not change: 20 Δmu_s + 60 Δmu_r = 0.
  const std::vector<double>& si = s.identifiability.undetermined[0].si_direction;
  CHECK(std::abs(20 * si[0] + 60 * si[1]) < 1e-6 * (20 * std::abs(si[0]) + 60 * std::abs(si[1])));

  // The flow measurement's sensitivities (per unit, standardised by sqrt(u² + sem²)).
  const std::vector<double> scale = SiPerUnit(Space(), s.candidates[s.best].unit);
  const double sd = std::hypot(0.1, 0.02);
  const std::vector<CandidateTarget> extra{{"flow", {8 * scale[0] / sd, -3 * scale[1] / sd}},
                                           {"second angle", {40 * scale[0], 120 * scale[1]}}};
  const std::vector<TargetGain> g =
      RankCandidateTargets(s.jacobian, extra, {"mu_s", "mu_r"}, scale);
  CHECK(g[0].lifts_valley);
  CHECK(std::isfinite(g[0].sigma_after[0]));
  CHECK(std::isfinite(g[0].sigma_after[1]));
  CHECK_FALSE(g[1].lifts_valley);

  // With both targets, σ is finite and what the gain predicted.
  LinearTargets both = Model(1, 2);
  const CalibrationSummary s2 = Calibrate(both, Space(), Measured(1, 2), Ceres());
  INFO(s2.BriefReport(Space()));
  REQUIRE(s2.termination == Termination::kWithinNoise);
  for (int k = 0; k < 2; ++k) {
    CHECK(s2.estimates[k].identifiable);
    CHECK(s2.estimates[k].sigma == Approx(g[0].sigma_after[k]).epsilon(0.05));
  }
  CHECK(s2.identifiability.Identifiable());
  CHECK(s2.covariance_note.find("ceres::Covariance") != std::string::npos);
}

TEST_CASE(
    "two targets: the spread of recovered values over 20 noise seeds matches the reported "
    "sigma",
    "[unit][calibrate]") {
  constexpr int kSeeds = 20;
  std::vector<std::vector<double>> recovered(2);
  std::vector<double> sigma(2, 0.0);
  for (uint64_t seed = 1; seed <= kSeeds; ++seed) {
    LinearTargets model = Model(seed, 2);
    const CalibrationSummary s = Calibrate(model, Space(), Measured(seed, 2), Ceres());
    REQUIRE(s.termination == Termination::kWithinNoise);
    for (int k = 0; k < 2; ++k) {
      REQUIRE(std::isfinite(s.estimates[k].sigma));
      recovered[k].push_back(s.estimates[k].value);
      sigma[k] += s.estimates[k].sigma / kSeeds;
    }
    CHECK(std::abs(s.correlation(0, 1)) <= 1.0);
  }
  for (int k = 0; k < 2; ++k) {
    double mean = 0, var = 0;
    for (double v : recovered[k]) mean += v / kSeeds;
    for (double v : recovered[k]) var += (v - mean) * (v - mean) / (kSeeds - 1);
    const double ratio = std::sqrt(var) / sigma[k];
    INFO("parameter " << k << ": spread " << std::sqrt(var) << ", reported sigma " << sigma[k]);
    CHECK(ratio >= 0.5);
    CHECK(ratio <= 2.0);
    CHECK(std::abs(mean - kTruth[k]) <= 3 * sigma[k] / std::sqrt(double(kSeeds)) + 1e-12);
  }
}

TEST_CASE("the driver asks in batches, is deterministic, and treats NaN as infeasible",
          "[unit][calibrate]") {
  CalibrationOptions o;
  o.optimiser = "differential_evolution";
  o.optimiser_options.max_evaluations = 120;
  o.optimiser_options.batch_size = 6;
  LinearTargets a = Model(2, 2), b = Model(2, 2);
  a.nan_above = b.nan_above = 0.8;
  const CalibrationSummary sa = Calibrate(a, Space(), Measured(2, 2), o);
  const CalibrationSummary sb = Calibrate(b, Space(), Measured(2, 2), o);
  INFO(sa.BriefReport(Space()));
  CHECK(a.batch_sizes == b.batch_sizes);
  REQUIRE(sa.candidates.size() == sb.candidates.size());
  for (size_t i = 0; i < sa.candidates.size(); ++i)
    CHECK(sa.candidates[i].unit == sb.candidates[i].unit);
  for (size_t n : a.batch_sizes) CHECK(n >= 6);
  int nan = 0;
  for (const Candidate& c : sa.candidates)
    if (c.parameters[0] > 0.8) {
      ++nan;
      CHECK_FALSE(c.trial.ok);
    }
  CHECK(nan > 0);  // the start (mu_s = 0.9) is one
  CHECK(sa.termination == Termination::kWithinNoise);
  CHECK(sa.candidates[sa.best].parameters[0] <= 0.8);
}

TEST_CASE("driver options and targets are checked before anything runs", "[unit][calibrate]") {
  LinearTargets m = Model(1, 2);
  std::vector<Target> t = Measured(1, 2);
  t[1].uncertainty = 0;
  CHECK(Calibrate(m, Space(), t, Ceres()).message.find("targets[1].uncertainty") !=
        std::string::npos);
  t = Measured(1, 2);
  t[1].name = t[0].name;
  CHECK(Calibrate(m, Space(), t, Ceres()).message.find("targets[1].name") != std::string::npos);
  CalibrationOptions o = Ceres();
  o.optimiser_options.batch_size = 0;
  CHECK(Calibrate(m, Space(), Measured(1, 2), o).message.find("batch_size") != std::string::npos);
  CHECK(Calibrate(m, Space(), {}, Ceres()).termination == Termination::kInvalid);
  CHECK(m.batch_sizes.empty());
}
