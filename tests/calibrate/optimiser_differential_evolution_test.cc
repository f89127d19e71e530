// "differential_evolution" on a two-basin analytic stand-in: a local optimiser started in the
// wrong basin stays there, the seeded batch search finds the match; batches, determinism,
// failed samples.
#include <catch2/catch.hpp>
#include <cmath>

#include "analytic_models.h"
#include "calibrate/optimiser.h"

using namespace demcal::calibrate;
using demcal::calibrate::testing::OffsetTargets;
using demcal::calibrate::testing::Recorder;

namespace {

// One residual with a match (|r| <= 1) only near (0.8, 0.75) and a local minimum near
// (0.2, 0.25) where |r| stays above 1.
TrialResult TwoBasins(const std::vector<double>& u) {
  const double a = (u[0] - 0.8) * (u[0] - 0.8) + (u[1] - 0.75) * (u[1] - 0.75);
  const double b = (u[0] - 0.2) * (u[0] - 0.2) + (u[1] - 0.25) * (u[1] - 0.25) + 0.05;
  return {true, {60 * a * b}, {0.1}};
}

}  // namespace

TEST_CASE("differential_evolution finds the match of a two-basin problem a local search misses",
          "[unit][calibrate]") {
  const std::vector<double> start{0.25, 0.3};
  const OptimiserResult local = NloptBobyqa(Batched(TwoBasins), start, {.max_evaluations = 60});
  CHECK(local.termination != Termination::kWithinNoise);  // the problem really is multi-modal
  CHECK(local.best_unit[0] < 0.5);

  Recorder rec{TwoBasins};
  const OptimiserResult r = DifferentialEvolution(
      rec.Function(), start, {.max_evaluations = 200, .batch_size = 6, .seed = 11});
  INFO(r.message);
  REQUIRE(r.termination == Termination::kWithinNoise);
  CHECK(TwoBasins(r.best_unit).WithinNoise());
  CHECK(r.best_unit[0] > 0.6);
  CHECK(r.evaluations <= 200);
  CHECK(r.batches == static_cast<int>(rec.batches.size()));
  for (const auto& b : rec.batches) CHECK(b.size() >= 6);  // never fewer than batch_size
  CHECK(rec.batches[0][0] == start);                       // the start is a member
}

TEST_CASE("differential_evolution is deterministic for a seed and differs between seeds",
          "[unit][calibrate]") {
  Recorder a{TwoBasins}, b{TwoBasins}, c{TwoBasins};
  const OptimiserOptions o{.max_evaluations = 40, .batch_size = 4, .seed = 3};
  DifferentialEvolution(a.Function(), {0.5, 0.5}, o);
  DifferentialEvolution(b.Function(), {0.5, 0.5}, o);
  OptimiserOptions other = o;
  other.seed = 4;
  DifferentialEvolution(c.Function(), {0.5, 0.5}, other);
  CHECK(a.batches == b.batches);
  CHECK(a.batches != c.batches);
}

TEST_CASE("differential_evolution keeps to the budget and steps over failed samples",
          "[unit][calibrate]") {
  Recorder rec{
      [](const std::vector<double>& u) { return u[1] < 0.5 ? TrialResult{} : TwoBasins(u); }};
  const OptimiserResult r =
      DifferentialEvolution(rec.Function(), {0.3, 0.3}, {.max_evaluations = 150, .batch_size = 5});
  CHECK(static_cast<int>(rec.Points().size()) == r.evaluations);
  CHECK(r.evaluations <= 150);
  CHECK(r.termination == Termination::kWithinNoise);
  CHECK(r.best_unit[1] >= 0.5);

  Recorder cut{[](const std::vector<double>& u) {  // never within noise
    TrialResult t = TwoBasins(u);
    t.residuals[0] += 5;
    return t;
  }};
  const OptimiserResult b =
      DifferentialEvolution(cut.Function(), {0.3, 0.3}, {.max_evaluations = 13, .batch_size = 5});
  CHECK(b.evaluations == 13);  // generations of 10, the second cut to the budget
  CHECK(cut.batches.back().size() == 3);
  CHECK(b.termination == Termination::kBudget);
}

TEST_CASE("differential_evolution with more targets than parameters searches on past a match",
          "[unit][calibrate]") {
  // As the ceres test of the same name: one parameter, six noise-free targets
  // r_k = 4 (u − 0.5) + b_k with mean-zero offsets (least-squares u = 0.5, χ²_min = 1.5,
  // σ_u = 0.10). The start u = 0.3 (2σ off) already matches jointly (χ² 5.34 ≤ χ²_6(68 %) = 7.04);
  // a first-match stop would end there. Settled (χ² ≤ 1) is out of reach, so the population
  // must close in on the estimate and the termination still says within_noise.
  const std::vector<double> b = {0.5, -0.5, 0.5, -0.5, 0.5, -0.5};
  auto model = [&](const std::vector<double>& u) { return OffsetTargets(b, u); };
  REQUIRE(model({0.3}).WithinNoise());
  REQUIRE_FALSE(model({0.5}).Settled(1));
  const OptimiserResult r = DifferentialEvolution(Recorder{model}.Function(), {0.3},
                                                  {.max_evaluations = 300, .batch_size = 6, .seed = 5});
  INFO(r.message);
  CHECK(r.termination == Termination::kWithinNoise);
  REQUIRE(r.best_unit.size() == 1);
  CHECK(r.best_unit[0] == Approx(0.5).margin(0.01));  // 0.1 σ
  CHECK(r.evaluations > 6);                            // not stopped in the first generation

  // With smaller offsets the estimate settles (χ²_min = 0.24 ≤ 1): the search stops there,
  // inside the 1σ region (σ_u = 0.10), before its budget.
  const std::vector<double> small = {0.2, -0.2, 0.2, -0.2, 0.2, -0.2};
  auto settling = [&](const std::vector<double>& u) { return OffsetTargets(small, u); };
  const OptimiserResult s = DifferentialEvolution(Recorder{settling}.Function(), {0.3},
                                                  {.max_evaluations = 300, .batch_size = 6, .seed = 5});
  INFO(s.message);
  CHECK(s.termination == Termination::kWithinNoise);
  CHECK(settling(s.best_unit).Settled(1));
  CHECK(std::fabs(s.best_unit[0] - 0.5) <= 0.1);
  CHECK(s.evaluations < 300);
}
