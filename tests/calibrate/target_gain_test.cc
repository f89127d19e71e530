// "Which measurement would help": a candidate target with independent sensitivities lifts the
// valley of one target (σ from +∞ to finite); one proportional to the existing target does not.
#include "calibrate/target_gain.h"

#include <catch2/catch.hpp>
#include <cmath>

#include "calibrate/parameter_covariance.h"

using namespace demcal::calibrate;

TEST_CASE("a target with independent sensitivities lifts a valley, a proportional one does not",
          "[unit][calibrate]") {
  Eigen::MatrixXd j(1, 2);
  j << 18, 52.8;
  const std::vector<CandidateTarget> candidates{{"discharge_time_s", {25, -6}},
                                                {"angle_deg (second heap)", {9, 26.4}}};
  const std::vector<TargetGain> g =
      RankCandidateTargets(j, candidates, {"mu_s", "mu_r"}, {0.9, 0.88});
  REQUIRE(g.size() == 2);
  CHECK(g[0].lifts_valley);
  CHECK(g[0].undetermined_before == 1);
  CHECK(g[0].undetermined_after == 0);
  for (int k = 0; k < 2; ++k) {
    CHECK(std::isinf(g[0].sigma_before[k]));
    CHECK(std::isfinite(g[0].sigma_after[k]));
    CHECK(g[0].identifiable_after[k]);
    CHECK(g[0].shrink[k] == 0);
  }
  // The σ it predicts is that of the two-row J.
  Eigen::MatrixXd both(2, 2);
  both << 18, 52.8, 25, -6;
  const ParameterCovariance c = CovarianceFromJacobian(both, {0.9, 0.88});
  CHECK(g[0].sigma_after[0] == Approx(c.sigma[0]));
  CHECK(g[0].description.find("lifts the valley") != std::string::npos);

  CHECK_FALSE(g[1].lifts_valley);  // the same combination again: still a valley
  CHECK(std::isinf(g[1].sigma_after[0]));
  CHECK(g[1].shrink[0] == 1);
}

TEST_CASE("an extra target shrinks finite sigmas by the information it adds", "[unit][calibrate]") {
  Eigen::MatrixXd j(2, 2);
  j << 10, 0, 0, 5;
  const std::vector<TargetGain> g =
      RankCandidateTargets(j, {{"more_of_p1", {0, 5}}}, {"p0", "p1"}, {1, 1});
  REQUIRE(g.size() == 1);
  CHECK_FALSE(g[0].lifts_valley);
  CHECK(g[0].shrink[0] == Approx(1.0));
  CHECK(g[0].shrink[1] == Approx(1 / std::sqrt(2.0)));  // information 25 → 50
  const std::vector<TargetGain> bad =
      RankCandidateTargets(j, {{"wrong", {1}}}, {"p0", "p1"}, {1, 1});
  CHECK(bad[0].description.find("ignored") != std::string::npos);
}
