// The clump-count verdict (paper section 2.4) from hand-made calibration summaries: which count
// is chosen, and which counts the data cannot tell apart. The residuals are made up to sit on
// either side of the joint within-noise rule for two targets (χ²₂ quantile at 68.27 % = 2.2957).
#include "workflow/calibration/clump_count_table.h"

#include <catch2/catch.hpp>
#include <cmath>

using demcal::calibrate::CalibrationSummary;
using demcal::calibrate::Candidate;
using namespace demcal::workflow;

namespace {

// One calibration whose only candidate has residuals r (in u) and simulation noise n (sem / u).
CalibrationSummary SummaryWith(double r1, double r2, double noise) {
  CalibrationSummary s;
  Candidate c;
  c.trial.ok = true;
  c.trial.residuals = {r1, r2};
  c.trial.noise = {noise, noise};
  s.candidates.push_back(c);
  s.best = 0;
  s.termination = c.trial.WithinNoise() ? demcal::calibrate::Termination::kWithinNoise
                                         : demcal::calibrate::Termination::kConverged;
  return s;
}

ClumpCountRow Row(int n, double r1, double r2, double noise) {
  return ClumpCountRowOf(n, SummaryWith(r1, r2, noise), 1.0);
}

}  // namespace

TEST_CASE("clump count: a single matching count is chosen and the others are excluded", "[unit][calibrate]") {
  const ClumpCountVerdict v = JudgeClumpCounts({Row(1, 6, 2, 0.5), Row(2, 0.5, -0.5, 0.5), Row(3, 3, 3, 0.5)});
  CHECK(v.chosen == 2);
  CHECK(v.matching == std::vector<int>{2});
  CHECK(v.not_told_apart.empty());
  CHECK(v.note.find("excluded") != std::string::npos);
}

TEST_CASE("clump count: counts that all agree are named as not told apart", "[unit][calibrate]") {
  const ClumpCountVerdict v = JudgeClumpCounts({Row(1, 6, 2, 0.5), Row(2, 0.8, 0.2, 0.5), Row(3, -0.3, 0.9, 0.5)});
  CHECK(v.chosen == 2);
  CHECK(v.not_told_apart == std::vector<int>{2, 3});
  CHECK(v.note.find("2, 3") != std::string::npos);
}

TEST_CASE("clump count: a smaller count that agrees only inconclusively is named, not dropped",
          "[unit][calibrate]") {
  // Count 3: Σ r²/(1+n²) = (1.5² + 1²)/(1 + 1.75²) = 0.80 ≤ 2.30, but noise 1.75 > 1: it agrees
  // and confirms nothing. Count 4 matches precisely. (The shape of the clump twin in
  // docs/calibration.md, where the generating count was 3.)
  const ClumpCountRow three = Row(3, 1.5, 1.0, 1.75);
  REQUIRE(three.agrees);
  REQUIRE_FALSE(three.within_noise);
  CHECK(three.agreeing_noise == Approx(1.75));
  const ClumpCountVerdict v = JudgeClumpCounts({Row(2, 5, 5, 0.5), three, Row(4, 0.5, 0.5, 0.5)});
  CHECK(v.chosen == 4);
  CHECK(v.not_told_apart == std::vector<int>{3, 4});
  CHECK(v.note.find("count(s) 3 agree but only inconclusively") != std::string::npos);
}

TEST_CASE("clump count: a count the noise cannot excuse does not agree", "[unit][calibrate]") {
  // Same residuals as above at noise 0.5: (2.25 + 1)/1.25 = 2.6 > 2.30, excluded.
  const ClumpCountRow row = Row(3, 1.5, 1.0, 0.5);
  CHECK_FALSE(row.agrees);
  CHECK(std::isnan(row.agreeing_noise));
  const ClumpCountVerdict v = JudgeClumpCounts({row});
  CHECK(v.chosen == -1);
  CHECK(v.not_told_apart.empty());
  CHECK(v.note.find("no count matched") != std::string::npos);
}
