// A candidate less precise than the measurement confirms nothing (TrialResult::Inconclusive):
// the driver re-runs it with more replicates before it may end a search, and such a candidate
// stops inflating the pooled spread of the others. Synthetic probe (synthetic_observable.h):
// angle = 15 + 60 μr deg plus seeded Gaussian noise of known σ.
#include <catch2/catch.hpp>
#include <cmath>

#include "calibrate/calibration.h"
#include "calibrate/evaluation_journal.h"
#include "calibrate/target_evaluator.h"
#include "core/io/scratch_dir.h"
#include "synthetic_observable.h"

using namespace demcal;
using namespace demcal::calibrate;
using demcal::calibrate::testing::OneMaterialModel;
using demcal::calibrate::testing::SyntheticAngle;

namespace {

ParameterSpace RollingSpace(double start) {
  ParameterSpace space;
  space.parameters.push_back({"mu_r", PairProperty::kRollingFriction, 0, 0, 0.02, 0.9, start});
  return space;
}

TargetEvaluator Evaluator(const SyntheticAngle& angle, const ParameterSpace& space, int replicates) {
  std::vector<RunGroup> groups{{"synthetic", &angle, OneMaterialModel(), space, {}, {}}};
  return TargetEvaluator(space, groups, {{0, "angle_deg"}}, {.replicates = replicates, .seed = 5},
                         nullptr);
}

}  // namespace

TEST_CASE("a trial within noise but noisier than the measurement is inconclusive, not a match",
          "[unit][calibrate]") {
  const TrialResult precise{true, {1.2}, {0.9}}, noisy{true, {1.2}, {3.0}}, off{true, {5}, {3.0}};
  CHECK(precise.WithinNoise());
  CHECK_FALSE(precise.Inconclusive());
  CHECK_FALSE(noisy.WithinNoise());  // |1.2| <= sqrt(1 + 9), but sem = 3 u: confirms nothing
  CHECK(noisy.Inconclusive());
  CHECK_FALSE(off.WithinNoise());
  CHECK_FALSE(off.Inconclusive());
}

TEST_CASE("a noisy candidate gets the replicates that make it as precise as the measurement",
          "[unit][calibrate]") {
  SyntheticAngle angle;
  angle.noise_deg = 1.0;  // 2 replicates: sem ≈ 0.7 deg, above the measurement's 0.35 deg
  const ParameterSpace space = RollingSpace(0.3);
  TargetEvaluator evaluator = Evaluator(angle, space, 2);
  const double measured = angle.base + angle.per_rolling * 0.3;  // the start is the truth
  CalibrationOptions options;
  options.max_replicate_factor = 10;  // room for the ≈ 8 replicates σ = 1, u = 0.35 need
  const CalibrationSummary s =
      Calibrate(evaluator, space, {{"angle", "angle_deg", measured, 0.35, "synthetic"}}, options);
  INFO(s.BriefReport(space));
  REQUIRE(s.termination == Termination::kWithinNoise);
  const Candidate& best = s.candidates[s.best];
  CHECK(best.replicates_added > 0);
  CHECK(best.trial.noise[0] <= kMatchNoise);
  CHECK(best.result.targets[0].replicates == 2 + best.replicates_added);
  CHECK(best.replicates_added <= 9 * 2);  // at most max_replicate_factor × 2 in all
  int runs = 0;
  for (const Candidate& c : s.candidates) runs += 2 + c.replicates_added;
  CHECK(angle.runs == runs);

  SECTION("without more replicates the same candidate is no match") {
    SyntheticAngle again;
    again.noise_deg = 1.0;
    TargetEvaluator fixed = Evaluator(again, space, 2);
    CalibrationOptions once;
    once.max_replicate_factor = 1;
    once.optimiser_options.max_evaluations = 4;
    const CalibrationSummary f =
        Calibrate(fixed, space, {{"angle", "angle_deg", measured, 0.35, "synthetic"}}, once);
    CHECK(f.termination != Termination::kWithinNoise);
    CHECK(f.candidates[0].trial.Inconclusive());
  }
}

TEST_CASE("a candidate given more replicates leaves the pooled spread", "[unit][calibrate]") {
  SyntheticAngle angle;
  angle.noise_deg = 0.5;
  angle.noisy_above_rolling = 0.8, angle.noisy_deg = 20;  // a rough heap at high μr
  const ParameterSpace space = RollingSpace(0.3);
  TargetEvaluator evaluator = Evaluator(angle, space, 2);
  evaluator.EvaluateBatch({{0.3}, {0.85}});
  const double inflated = evaluator.EvaluateBatch({{0.4}})[0].targets[0].sem;
  const std::optional<CandidateResult> rough = evaluator.AddReplicates({0.85}, 6);
  REQUIRE(rough);
  CHECK(rough->targets[0].replicates == 6);
  CHECK(rough->targets[0].sem > 20 * 0.2);  // its own spread: σ 20 deg over 6 replicates
  const double quiet = evaluator.EvaluateBatch({{0.5}})[0].targets[0].sem;
  // The pool now holds the three quiet candidates only: their common spread is σ 0.5 deg.
  CHECK(inflated > 10 * quiet);
  CHECK(quiet < 0.5);
  CHECK_FALSE(evaluator.AddReplicates({0.77}, 4));  // never evaluated
}

TEST_CASE("batch optimisers get noisy candidates re-run too, each in its own place",
          "[unit][calibrate]") {
  SyntheticAngle angle;
  angle.noise_deg = 1.0;
  const ParameterSpace space = RollingSpace(0.2);
  TargetEvaluator evaluator = Evaluator(angle, space, 2);
  CalibrationOptions options;
  options.optimiser = "ceres";
  options.optimiser_options.batch_size = 4;
  options.optimiser_options.max_evaluations = 24;
  const double measured = angle.base + angle.per_rolling * 0.3;
  const CalibrationSummary s =
      Calibrate(evaluator, space, {{"angle", "angle_deg", measured, 0.35, "synthetic"}}, options);
  INFO(s.BriefReport(space));
  REQUIRE(s.best >= 0);
  int runs = 0;
  for (const Candidate& c : s.candidates) {
    runs += 2 + c.replicates_added;
    // Each candidate's result is its own: its mean is its parameters' line plus noise.
    if (c.trial.ok)
      CHECK(std::abs(c.result.targets[0].mean - (angle.base + angle.per_rolling * c.parameters[0])) <
            4 * angle.noise_deg);
  }
  CHECK(angle.runs == runs);
  CHECK(evaluator.history().size() == s.candidates.size());
}

// A resumed calibration finds the replicates its candidates were given later in the journal
// too: every run of the first calibration counts as reused, none as run, none twice.
TEST_CASE("a resumed calibration counts the added replicates it finds in the journal as reused",
          "[unit][calibrate]") {
  demcal::testing::ScratchDir dir("replicate_escalation_resume");
  const std::string path = dir.str("journal.jsonl");
  const ParameterSpace space = RollingSpace(0.3);
  CalibrationOptions options;
  options.max_replicate_factor = 10;
  auto calibrate = [&](SyntheticAngle& angle) {
    angle.noise_deg = 1.0;  // 2 replicates are too few: candidates get more (Sharpen, Deepen)
    EvaluationJournal journal;
    std::string error;
    REQUIRE(journal.Open(path, "f", &error));
    std::vector<RunGroup> groups{{"synthetic", &angle, OneMaterialModel(), space, {}, {}}};
    TargetEvaluator evaluator(space, groups, {{0, "angle_deg"}}, {.replicates = 2, .seed = 5},
                              &journal);
    const double measured = angle.base + angle.per_rolling * 0.3;
    return Calibrate(evaluator, space, {{"angle", "angle_deg", measured, 0.35, "synthetic"}},
                     options);
  };
  SyntheticAngle first, second;
  const CalibrationSummary whole = calibrate(first);
  REQUIRE(whole.candidates[whole.best].replicates_added > 0);
  CHECK(whole.replicates_run == first.runs);
  CHECK(whole.replicates_reused == 0);
  const CalibrationSummary resumed = calibrate(second);
  CHECK(second.runs == 0);
  CHECK(resumed.replicates_run == 0);
  CHECK(resumed.replicates_reused == first.runs);
}
