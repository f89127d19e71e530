// The bracket optimiser on analytic residuals with a known root: k = 1 is the textbook Illinois
// regula falsi (Dowell & Jarratt 1971), one candidate a batch; k-section (bracket_points = k)
// finds the same root in fewer batches of up to k candidates.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>

#include "analytic_models.h"
#include "calibrate/optimiser.h"

using namespace demcal::calibrate;
using demcal::calibrate::testing::Recorder;

namespace {

// A steep convex residual, r(u) = A (e^{10u} − e^{10 u0}), slope 200 per unit at the root
// u0 = 0.35, so "within noise" (|r| ≤ 1, no simulation noise) means |u − u0| ≤ 0.005. Regula
// falsi converges slowly on it (the steep side is kept), which the Illinois step fixes.
constexpr double kRoot = 0.35;
double Residual(double u) {
  const double a = 200 / (10 * std::exp(10 * kRoot));
  return a * (std::exp(10 * u) - std::exp(10 * kRoot));
}
TrialResult Trial(const std::vector<double>& u) { return {true, {Residual(u[0])}, {0.0}}; }

// The Illinois iteration written out on its own, for a start below the root: the start, the
// upper bound, then the regula-falsi points, each point's residual deciding the next.
std::vector<double> Illinois(double start, double tol, int budget) {
  std::vector<double> seq{start, 1.0};
  double a = start, b = 1.0, fa = Residual(a), fb = Residual(b);
  int kept = 0;
  while (b - a > tol && static_cast<int>(seq.size()) < budget) {
    const double u =
        std::clamp(b - fb * (b - a) / (fb - fa), a + 0.01 * (b - a), b - 0.01 * (b - a));
    seq.push_back(u);
    const double r = Residual(u);
    if (std::abs(r) <= 1) break;
    if (r * fa < 0) {
      b = u, fb = r;
      if (kept == 1) fa *= 0.5;
      kept = 1;
    } else {
      a = u, fa = r;
      if (kept == -1) fb *= 0.5;
      kept = -1;
    }
  }
  return seq;
}

OptimiserResult Run(Recorder* rec, int k, int budget = 40) {
  rec->trial = Trial;
  return BracketOptimise(rec->Function(), {0.1}, {.max_evaluations = budget, .bracket_points = k});
}

}  // namespace

TEST_CASE("bracket, one point a round: the Illinois regula falsi, one candidate a batch",
          "[unit][calibrate]") {
  Recorder rec;
  const OptimiserResult r = Run(&rec, 1);
  REQUIRE(r.termination == Termination::kWithinNoise);
  CHECK(std::abs(r.best_unit[0] - kRoot) <= 0.005);
  std::vector<double> asked;
  for (const auto& batch : rec.batches) {
    REQUIRE(batch.size() == 1);
    asked.push_back(batch[0][0]);
  }
  CHECK(asked == Illinois(0.1, 0.002, 40));  // exactly, point for point
  CHECK(r.batches == static_cast<int>(rec.batches.size()));
  CHECK(r.evaluations == r.batches);
}

TEST_CASE("bracket, k points a round: the same root in fewer rounds", "[unit][calibrate]") {
  Recorder one;
  const OptimiserResult r1 = Run(&one, 1);
  for (int k : {2, 4, 8}) {
    Recorder rec;
    const OptimiserResult r = Run(&rec, k);
    INFO("k = " << k << ": " << r.message);
    REQUIRE(r.termination == Termination::kWithinNoise);
    CHECK(std::abs(r.best_unit[0] - kRoot) <= 0.005);
    CHECK(r.batches < r1.batches);
    CHECK(r.batches == static_cast<int>(rec.batches.size()));
    REQUIRE(rec.batches[0] == std::vector<std::vector<double>>{{0.1}, {0.0}, {1.0}});
    for (size_t b = 1; b < rec.batches.size(); ++b) {
      CHECK(rec.batches[b].size() <= static_cast<size_t>(k));
      CHECK(std::is_sorted(rec.batches[b].begin(), rec.batches[b].end()));
    }
    // Deterministic: the same k asks for the same candidates (what a farmed run relies on).
    Recorder again;
    Run(&again, k);
    CHECK(again.batches == rec.batches);
  }
}

TEST_CASE("bracket, k points a round: the budget caps a round, never exceeded",
          "[unit][calibrate]") {
  for (int budget : {1, 2, 3, 4, 6, 9}) {
    Recorder rec;
    const OptimiserResult r = Run(&rec, 4, budget);
    INFO("budget " << budget << ": " << r.message);
    CHECK(static_cast<int>(rec.Points().size()) <= budget);
    CHECK(r.evaluations == static_cast<int>(rec.Points().size()));
    CHECK((r.termination == Termination::kBudget || r.termination == Termination::kWithinNoise));
  }
}

TEST_CASE("bracket, k points a round: a bound without a value is retreated from",
          "[unit][calibrate]") {
  Recorder rec;
  rec.trial = [](const std::vector<double>& u) {
    return u[0] > 0.9 ? TrialResult{} : Trial(u);  // the heaps never settle near the top
  };
  const OptimiserResult r =
      BracketOptimise(rec.Function(), {0.1}, {.max_evaluations = 40, .bracket_points = 3});
  REQUIRE(r.termination == Termination::kWithinNoise);
  CHECK(std::abs(r.best_unit[0] - kRoot) <= 0.005);
  CHECK(r.message.find("probed nearer the start") != std::string::npos);
  CHECK(rec.batches[1] == std::vector<std::vector<double>>{{0.55}});  // half-way from 1 to 0.1
}

TEST_CASE("bracket, k points a round: a candidate without a value leaves the bracket wider",
          "[unit][calibrate]") {
  Recorder rec;
  rec.trial = [](const std::vector<double>& u) {
    return u[0] > 0.6 && u[0] < 0.9 ? TrialResult{} : Trial(u);  // no value on (0.6, 0.9)
  };
  const OptimiserResult r =
      BracketOptimise(rec.Function(), {0.1}, {.max_evaluations = 40, .bracket_points = 3});
  REQUIRE(r.termination == Termination::kWithinNoise);
  CHECK(std::abs(r.best_unit[0] - kRoot) <= 0.005);
  CHECK(r.message.find("gave no value") != std::string::npos);
  // The first round, in [0.1, 1]: the secant point, 0.4 and 0.7; 0.7 gave no value.
  REQUIRE(rec.batches.size() > 1);
  CHECK(rec.batches[1].size() == 3);
  CHECK(rec.batches[1][2][0] == Approx(0.7));
}

TEST_CASE("bracket, k points a round: out of reach is still said", "[unit][calibrate]") {
  Recorder rec;
  rec.trial = [](const std::vector<double>& u) {
    return TrialResult{true, {Residual(u[0]) - 1e6}, {0.0}};
  };
  const OptimiserResult r =
      BracketOptimise(rec.Function(), {0.1}, {.max_evaluations = 40, .bracket_points = 4});
  CHECK(r.termination == Termination::kOutOfRange);
  CHECK(rec.batches.size() == 1);  // the start and both bounds, one batch
}
