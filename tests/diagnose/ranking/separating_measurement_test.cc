// FindSeparatingMeasurement (separating_measurement.h): the observation where two effects'
// refits differ is named through calibrate's target gain.
#include "diagnose/ranking/separating_measurement.h"

#include <catch2/catch.hpp>

namespace demcal::diagnose {

TEST_CASE("the separating measurement is where the two effects' signatures differ", "[unit]") {
  // Four observations; the effects move the first three alike and only b moves the fourth.
  std::vector<Observation> obs;
  for (int i = 0; i < 4; ++i)
    obs.push_back(
        {"o" + std::to_string(i), "angle_deg", {{"coating_wt_pct", std::to_string(i)}}, 30, 1.0});
  obs[3].experiment = "aor.json";
  const Eigen::MatrixXd Js = Eigen::MatrixXd::Zero(4, 0);
  Eigen::VectorXd sa(4), sb(4), ra(4), rb(4);
  sa << 1, 1, 1, 0;
  sb << 1, 1, 1, 2;
  ra << 0.1, -0.1, 0.2, 0.0;
  rb << 0.1, -0.1, 0.2, 1.5;
  const SeparatingMeasurement m =
      FindSeparatingMeasurement(Js, sa, sb, ra, rb, Eigen::VectorXd::Ones(4), obs, "a", "b");
  CHECK(m.observation == 3);
  CHECK(m.separates);
  CHECK(m.difference_sigma == Approx(1.5));
  CHECK(m.prediction_b == Approx(31.5));
  CHECK(m.description.find("aor.json") != std::string::npos);
  // Identical refits everywhere: no observation of the study separates them.
  const SeparatingMeasurement none =
      FindSeparatingMeasurement(Js, sa, sb, ra, ra, Eigen::VectorXd::Ones(4), obs, "a", "b");
  CHECK_FALSE(none.separates);
  CHECK(none.description.find("a new observable") != std::string::npos);
}

}  // namespace demcal::diagnose
