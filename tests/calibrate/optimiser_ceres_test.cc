// The "ceres" optimiser on analytic stand-ins (no DEM): linear and nonlinear residuals with
// known noise, a failing region, a valley, the budget, determinism.
#include <Eigen/Dense>
#include <catch2/catch.hpp>
#include <cmath>

#include "analytic_models.h"
#include "calibrate/optimiser.h"

using namespace demcal::calibrate;
using demcal::calibrate::testing::Normal;
using demcal::calibrate::testing::OffsetTargets;
using demcal::calibrate::testing::Recorder;

namespace {

// Two targets, linear in the unit cube, truth (0.6, 0.3), simulation noise 0.2 (standardised)
// drawn once per seed (common random numbers).
TrialResult Linear(const std::vector<double>& u, uint64_t seed) {
  const double r1 = 8 * (u[0] - 0.6) + 3 * (u[1] - 0.3) + 0.2 * Normal(seed, 0);
  const double r2 = -2 * (u[0] - 0.6) + 9 * (u[1] - 0.3) + 0.2 * Normal(seed, 1);
  return {true, {r1, r2}, {0.2, 0.2}};
}

bool InCube(const std::vector<std::vector<double>>& points) {
  for (const auto& p : points)
    for (double v : p)
      if (v < 0 || v > 1) return false;
  return true;
}

}  // namespace

TEST_CASE("ceres matches a linear two-target model within noise, asking for differences in batches",
          "[unit][calibrate]") {
  Recorder rec{[](const std::vector<double>& u) { return Linear(u, 3); }};
  const OptimiserResult r = CeresOptimise(rec.Function(), {0.1, 0.9}, {.max_evaluations = 40});
  INFO(r.message);
  REQUIRE(r.termination == Termination::kWithinNoise);
  CHECK(Linear(r.best_unit, 3).WithinNoise());
  CHECK(r.evaluations <= 40);
  CHECK(r.evaluations == static_cast<int>(rec.Points().size()));
  CHECK(InCube(rec.Points()));
  size_t largest = 0;
  for (const auto& b : rec.batches) largest = std::max(largest, b.size());
  CHECK(largest >= 3);  // centre and the offsets of both parameters as one batch
}

TEST_CASE("ceres with more targets than parameters searches on past a match until it settles",
          "[unit][calibrate]") {
  // One parameter, six noise-free targets r_k = 4 (u − 0.5) + b_k with offsets b_k whose mean is
  // 0 (so the least-squares u is 0.5, χ²_min = Σ b² = 1.5). Every u with χ² ≤ χ²_6(68 %) = 7.04 is
  // a match: |u − 0.5| ≤ 0.29, i.e. up to 2.4 σ (σ_u = 1 / sqrt(6 · 16) = 0.10) from the estimate.
  // Settled (χ² ≤ 1 for one parameter) cannot be reached, so the search runs to Ceres'
  // tolerance and must end at the estimate, still reported as within_noise.
  const std::vector<double> b = {0.5, -0.5, 0.5, -0.5, 0.5, -0.5};
  auto model = [&](const std::vector<double>& u) { return OffsetTargets(b, u); };
  const OptimiserResult r = CeresOptimise(Recorder{model}.Function(), {0.3}, {.max_evaluations = 40});
  INFO(r.message);
  CHECK(model({0.3}).WithinNoise());  // the start (2 σ off) already matches: 6 · 0.64 + 1.5 = 5.34 ≤ 7.04
  CHECK(r.termination == Termination::kWithinNoise);
  REQUIRE(r.best_unit.size() == 1);
  CHECK(r.best_unit[0] == Approx(0.5).margin(0.01));  // 0.1 σ
}

TEST_CASE("ceres finite-difference step exceeds the noise", "[unit][calibrate]") {
  // Noise 0.5: the step is clamp(4·0.5/sqrt(12), 0.01, 0.25) = 0.25 of the range.
  Recorder rec{[](const std::vector<double>& u) {
    TrialResult t = Linear(u, 1);
    t.noise = {0.5, 0.5};
    return t;
  }};
  CeresOptimise(rec.Function(), {0.5, 0.5}, {.max_evaluations = 40});
  REQUIRE(rec.batches.size() >= 2);
  const auto& fd = rec.batches[1];  // the first Jacobian: centre + offsets
  REQUIRE(fd.size() >= 2);
  double step = 0;
  for (const auto& p : fd) step = std::max(step, std::abs(p[0] - 0.5) + std::abs(p[1] - 0.5));
  CHECK(step == Approx(0.25));
}

TEST_CASE("ceres solves a nonlinear model and stays inside the bounds", "[unit][calibrate]") {
  auto model = [](const std::vector<double>& u) -> TrialResult {
    const double r1 = (std::exp(2 * u[0]) - std::exp(0.6)) / 0.05;
    const double r2 = (u[0] * u[1] - 0.3 * 0.7) / 0.02;
    return {true, {r1, r2}, {0.05, 0.05}};
  };
  Recorder rec{model};
  const OptimiserResult r = CeresOptimise(rec.Function(), {0.9, 0.1}, {.max_evaluations = 60});
  INFO(r.message);
  REQUIRE(r.termination == Termination::kWithinNoise);
  CHECK(model(r.best_unit).WithinNoise());
  CHECK(InCube(rec.Points()));
}

TEST_CASE("ceres treats failed samples as infeasible and still finds the match",
          "[unit][calibrate]") {
  int failures = 0;
  Recorder rec{[&](const std::vector<double>& u) {
    if (u[0] > 0.75) return ++failures, TrialResult{};  // "the heap never settles"
    return Linear(u, 2);
  }};
  const OptimiserResult r = CeresOptimise(rec.Function(), {0.2, 0.2}, {.max_evaluations = 60});
  INFO(r.message);
  CHECK(r.termination == Termination::kWithinNoise);
  CHECK(r.best_unit[0] <= 0.75);
  CHECK(Linear(r.best_unit, 2).WithinNoise());
}

TEST_CASE("ceres is deterministic: the same answers give the same candidates",
          "[unit][calibrate]") {
  Recorder a{[](const std::vector<double>& u) { return Linear(u, 4); }};
  Recorder b{[](const std::vector<double>& u) { return Linear(u, 4); }};
  CeresOptimise(a.Function(), {0.95, 0.05}, {.max_evaluations = 40});
  CeresOptimise(b.Function(), {0.95, 0.05}, {.max_evaluations = 40});
  CHECK(a.batches == b.batches);
}

TEST_CASE("ceres stops at the budget and reports it", "[unit][calibrate]") {
  Recorder rec{[](const std::vector<double>& u) { return Linear(u, 5); }};
  const OptimiserResult r = CeresOptimise(rec.Function(), {0.0, 1.0}, {.max_evaluations = 4});
  CHECK(r.termination == Termination::kBudget);
  CHECK(r.evaluations <= 4);
  CHECK(static_cast<int>(rec.Points().size()) == r.evaluations);
}

TEST_CASE("ceres covariance: finite for two targets, refused on a valley", "[unit][calibrate]") {
  // Noise-free linear model: ceres::Covariance must equal (JᵀJ)⁻¹ of the exact J.
  auto exact = [](const std::vector<double>& u) -> TrialResult {
    return {
        true, {8 * (u[0] - 0.6) + 3 * (u[1] - 0.3), -2 * (u[0] - 0.6) + 9 * (u[1] - 0.3)}, {0, 0}};
  };
  const OptimiserResult r = CeresOptimise(Batched(exact), {0.1, 0.9}, {.max_evaluations = 40});
  REQUIRE(r.covariance_unit.size() == 4);
  Eigen::Matrix2d j;
  j << 8, 3, -2, 9;
  const Eigen::Matrix2d expected = (j.transpose() * j).inverse();
  for (int a = 0; a < 2; ++a)
    for (int b = 0; b < 2; ++b)
      CHECK(r.covariance_unit[a * 2 + b] == Approx(expected(a, b)).epsilon(1e-6));

  // One target, two parameters: J is 1×2 and rank-deficient.
  auto valley = [](const std::vector<double>& u) -> TrialResult {
    return {true, {10 * (u[0] - 0.5) + 5 * (u[1] - 0.5)}, {0.1}};
  };
  const OptimiserResult v = CeresOptimise(Batched(valley), {0.05, 0.05}, {.max_evaluations = 40});
  CHECK(v.termination == Termination::kWithinNoise);
  CHECK(v.covariance_unit.empty());
  CHECK(v.covariance_note.find("rank-deficient") != std::string::npos);
}

// DEM noise is chaotic: any change of the parameters, however small, gives another packing and
// another value (common random numbers do not make it smooth). A rejected step then made Ceres
// shrink its trust region towards the same centre and ask for new stencils 1e-3, 1e-5, 1e-8
// away (the DEM twin of examples/calibrate_bp_two_targets.json). On the candidate lattice no two
// candidates are closer than unit_tolerance, and the budget is not spent on them.
TEST_CASE("ceres never asks for candidates closer than the unit tolerance", "[unit][calibrate]") {
  auto chaotic = [](const std::vector<double>& u) {
    const double hash = std::sin(1e7 * u[0] + 3e7 * u[1]);  // a new "packing" for any change
    const double r1 = 2 * (u[0] - 0.6) + 3.5 * hash;         // noise larger than the signal
    const double r2 = 9 * (u[1] - 0.3) + 3.5 * std::cos(7e6 * u[0]);
    return TrialResult{true, {r1, r2}, {3.5, 3.5}};
  };
  Recorder rec{chaotic};
  const OptimiserOptions options{.max_evaluations = 60, .unit_tolerance = 0.002};
  const OptimiserResult r = CeresOptimise(rec.Function(), {0.62, 0.1}, options);
  INFO(r.message);
  const auto points = rec.Points();
  for (size_t a = 0; a < points.size(); ++a)
    for (size_t b = 0; b < a; ++b) {
      double gap = 0;
      for (size_t k = 0; k < 2; ++k) gap = std::max(gap, std::abs(points[a][k] - points[b][k]));
      CHECK(gap >= 0.002 - 1e-12);
    }
  CHECK(r.evaluations == static_cast<int>(points.size()));
}
