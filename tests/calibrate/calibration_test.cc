// Calibration twin tests (docs/design.md, Conventions): data generated from known parameters by a
// cheap synthetic probe (one run group, one target, through the TargetEvaluator as every study
// runs), recovered by the calibration; resumption from the journal.
#include "calibrate/calibration.h"

#include <catch2/catch.hpp>
#include <filesystem>
#include <unistd.h>

#include "calibrate/target_evaluator.h"
#include "synthetic_observable.h"

using namespace demcal;
using namespace demcal::calibrate;
using testing::OneMaterialModel;
using testing::SyntheticAngle;

namespace {

ParameterSpace RollingSpace() {
  ParameterSpace space;
  space.parameters.push_back({"mu_r", PairProperty::kRollingFriction, 0, 0, 0.02, 0.9, 0.1});
  return space;
}

std::string FreshJournal(const std::string& name) {
  // One folder per process: ctest runs test cases side by side.
  const auto dir = std::filesystem::temp_directory_path() /
                   ("demcal_calibration_test_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  std::filesystem::remove(dir / name);
  return (dir / name).string();
}

CalibrationSummary Run(const SyntheticAngle& angle, const ParameterSpace& space, double target,
                       const CalibrationOptions& options, EvaluationJournal* journal = nullptr) {
  std::vector<RunGroup> groups{{"synthetic", &angle, OneMaterialModel(), space, {}, {}}};
  TargetEvaluator evaluator(space, groups, {{0, "angle_deg"}}, {.replicates = 3, .seed = 5}, journal);
  return Calibrate(evaluator, space, {{"angle", "angle_deg", target, 0.5, "twin"}}, options);
}

const std::vector<double>& BestParameters(const CalibrationSummary& s) {
  return s.candidates[s.best].parameters;
}

double Sigma(const CalibrationSummary& s, size_t k) { return s.estimates[k].sigma; }

// d angle / d parameter k (deg per SI unit) from the standardised sensitivity matrix: undo the
// 1/sqrt(1 + noise²) weight and the measurement uncertainty, divide by the bounds' range.
double Slope(const CalibrationSummary& s, const ParameterSpace& space, size_t k) {
  const double noise = s.candidates[s.best].trial.noise[0];
  const auto& p = space.parameters[k];
  return s.jacobian(0, k) * std::sqrt(1 + noise * noise) * 0.5 / (p.upper - p.lower);
}

}  // namespace

TEST_CASE("calibration twin: bracket recovers the rolling friction that made the data", "[unit][calibrate]") {
  SyntheticAngle angle;
  const double truth = 0.3, measured = angle.base + angle.per_rolling * truth;  // 33 deg
  const CalibrationSummary s = Run(angle, RollingSpace(), measured, {});
  INFO(s.BriefReport(RollingSpace()));
  REQUIRE(s.termination == Termination::kWithinNoise);
  REQUIRE(s.estimates.size() == 1);
  CHECK(Sigma(s, 0) > 0);
  CHECK(std::abs(BestParameters(s)[0] - truth) <= 2 * Sigma(s, 0));
  CHECK(Slope(s, RollingSpace(), 0) == Approx(angle.per_rolling).epsilon(0.05));  // common random numbers
  CHECK(s.candidates.size() <= 6);
  CHECK(angle.runs == 3 * static_cast<int>(s.candidates.size()));
}

TEST_CASE("calibration says when the measurement is out of the bounds' reach", "[unit][calibrate]") {
  SyntheticAngle angle;
  const CalibrationSummary s = Run(angle, RollingSpace(), 80.0, {});  // needs mu_r ≈ 1.08 > 0.9
  CHECK(s.termination == Termination::kOutOfRange);
  CHECK(s.message.find("outside the range") != std::string::npos);
  CHECK(BestParameters(s)[0] == Approx(0.9));  // the nearest candidate: the bound
}

TEST_CASE("calibration resumes from its journal without repeating finished runs", "[unit][calibrate]") {
  const double measured = 38.0;
  SyntheticAngle uninterrupted;
  const CalibrationSummary whole = Run(uninterrupted, RollingSpace(), measured, {});
  REQUIRE(whole.candidates.size() >= 3);

  const std::string path = FreshJournal("resume.jsonl");
  std::string error;
  SyntheticAngle first, second;
  CalibrationOptions cut;
  cut.optimiser_options.max_evaluations = 2;  // "killed" after two candidates
  {
    EvaluationJournal journal;
    REQUIRE(journal.Open(path, "twin", &error));
    CHECK(Run(first, RollingSpace(), measured, cut, &journal).termination == Termination::kBudget);
  }
  EvaluationJournal journal;
  REQUIRE(journal.Open(path, "twin", &error));
  const CalibrationSummary resumed = Run(second, RollingSpace(), measured, {}, &journal);
  CHECK(resumed.replicates_reused == first.runs);
  CHECK(first.runs + second.runs == uninterrupted.runs);
  REQUIRE(resumed.best >= 0);
  CHECK(BestParameters(resumed) == BestParameters(whole));
  CHECK(resumed.candidates[resumed.best].result.targets[0].mean ==
        whole.candidates[whole.best].result.targets[0].mean);
}

TEST_CASE("failed runs are a status: the bracket retreats from a bound that gives no value", "[unit][calibrate]") {
  SyntheticAngle angle;
  angle.fail_above_rolling = 0.6;  // the upper bound (0.9) never settles; 0.5 does
  const CalibrationSummary s = Run(angle, RollingSpace(), 42.0, {});  // truth mu_r = 0.45
  CHECK(s.termination == Termination::kWithinNoise);
  CHECK(s.message.find("probed nearer the start") != std::string::npos);
  bool saw_failure = false;
  for (const Candidate& c : s.candidates)
    saw_failure = saw_failure || c.result.targets[0].status.find("not_settled") != std::string::npos;
  CHECK(saw_failure);
  CHECK(std::abs(BestParameters(s)[0] - 0.45) <= 2 * Sigma(s, 0));

  angle.fail_above_rolling = 0.0;  // nothing ever settles
  const CalibrationSummary none = Run(angle, RollingSpace(), 42.0, {});
  CHECK(none.termination == Termination::kFailed);
  CHECK(none.best == -1);
}

TEST_CASE("two parameters against one measurement: matched, but reported as a valley", "[unit][calibrate]") {
  SyntheticAngle angle;
  angle.per_sliding = 20;
  ParameterSpace space = RollingSpace();
  space.parameters.push_back({"mu_s", PairProperty::kSlidingFriction, 0, 0, 0.1, 1.0, 0.5});
  CalibrationOptions options;
  options.optimiser = "nlopt_bobyqa";
  options.optimiser_options.max_evaluations = 40;
  const CalibrationSummary s = Run(angle, space, 40.0, options);
  INFO(s.identifiability.summary);
  CHECK(s.termination == Termination::kWithinNoise);
  REQUIRE(s.estimates.size() == 2);
  for (size_t k = 0; k < 2; ++k) {
    CHECK_FALSE(s.estimates[k].identifiable);
    CHECK(std::isinf(Sigma(s, k)));  // never a finite sigma the data cannot support
  }
  CHECK(s.identifiability.summary.find("mu_s and mu_r trade off") != std::string::npos);
}

TEST_CASE("calibration options are checked before anything runs", "[unit][calibrate]") {
  SyntheticAngle angle;
  CalibrationOptions options;
  options.optimiser = "simulated_annealing";
  CHECK(Run(angle, RollingSpace(), 30.0, options).termination == Termination::kInvalid);
  options.optimiser = "bracket";
  options.optimiser_options.max_evaluations = 0;
  CHECK(Run(angle, RollingSpace(), 30.0, options).message.find("max_evaluations") != std::string::npos);
  CHECK(angle.runs == 0);
}

TEST_CASE("the batch optimisers resume from the journal without repeating finished runs",
          "[unit][calibrate]") {
  for (const std::string name : {"ceres", "differential_evolution"}) {
    INFO(name);
    CalibrationOptions options;
    options.optimiser = name;
    options.optimiser_options.max_evaluations = 30;
    const double measured = 38.0;  // mu_r ≈ 0.383
    SyntheticAngle uninterrupted;
    const CalibrationSummary whole = Run(uninterrupted, RollingSpace(), measured, options);
    REQUIRE(whole.termination == Termination::kWithinNoise);
    REQUIRE(whole.candidates.size() >= 3);
    CHECK(std::abs(BestParameters(whole)[0] - (measured - 15) / 60) <= 2 * Sigma(whole, 0));

    const std::string path = FreshJournal("resume_" + name + ".jsonl");
    std::string error;
    SyntheticAngle first, second;
    CalibrationOptions cut = options;
    cut.optimiser_options.max_evaluations = 2;  // "killed" after two candidates
    {
      EvaluationJournal journal;
      REQUIRE(journal.Open(path, "twin", &error));
      Run(first, RollingSpace(), measured, cut, &journal);
    }
    REQUIRE(first.runs > 0);
    EvaluationJournal journal;
    REQUIRE(journal.Open(path, "twin", &error));
    const CalibrationSummary resumed = Run(second, RollingSpace(), measured, options, &journal);
    CHECK(resumed.replicates_reused == first.runs);
    CHECK(first.runs + second.runs == uninterrupted.runs);
    REQUIRE(resumed.best >= 0);
    CHECK(BestParameters(resumed) == BestParameters(whole));
  }
}
