// The identifiability report: singular values, condition number and, in words, the parameter
// combination a single target leaves undetermined; the documented threshold sqrt(12).
#include "calibrate/identifiability.h"

#include <catch2/catch.hpp>
#include <cmath>

#include "calibrate/jacobian_svd.h"
#include "calibrate/parameter_covariance.h"

using namespace demcal::calibrate;

TEST_CASE("one target, two parameters: the valley is named with its direction",
          "[unit][calibrate]") {
  Eigen::MatrixXd j(1, 2);
  j << 18, 52.8;  // an angle: 20 deg per mu_s over 0.9, 60 deg per mu_r over 0.88 (u = 1 deg)
  const IdentifiabilityReport r = AnalyseIdentifiability(j, {"mu_s", "mu_r"}, {0.9, 0.88});
  REQUIRE(r.singular_values.size() == 2);
  CHECK(r.singular_values[0] == Approx(std::hypot(18, 52.8)));
  CHECK(r.singular_values[1] == 0);
  CHECK(std::isinf(r.condition_number));
  REQUIRE(r.undetermined.size() == 1);
  const UndeterminedDirection& d = r.undetermined[0];
  // Moving along it leaves the residual unchanged: J·v = 0, and it is the only such direction.
  CHECK(std::abs(18 * d.unit_direction[0] + 52.8 * d.unit_direction[1]) < 1e-9);
  CHECK(d.unit_direction[0] > 0);  // largest component positive: mu_s up, mu_r down
  CHECK(d.unit_direction[1] < 0);
  CHECK(std::isinf(d.sigma_unit));
  CHECK(d.si_direction[0] == Approx(d.unit_direction[0] * 0.9));
  CHECK(d.description.find("mu_s and mu_r trade off") != std::string::npos);
  CHECK(d.description.find("+1.00 mu_s ~ -0.34 mu_r") != std::string::npos);  // 18 / 52.8
  CHECK_FALSE(r.Identifiable());
}

TEST_CASE("two independent targets determine both parameters", "[unit][calibrate]") {
  Eigen::MatrixXd j(2, 2);
  j << 18, 52.8, 30, -4;
  const IdentifiabilityReport r = AnalyseIdentifiability(j, {"mu_s", "mu_r"}, {0.9, 0.88});
  CHECK(r.Identifiable());
  CHECK(std::isfinite(r.condition_number));
  CHECK(r.summary.find("every parameter is determined") != std::string::npos);
}

TEST_CASE("undetermined means a singular value at most sqrt(12)", "[unit][calibrate]") {
  Eigen::MatrixXd weak(2, 2), firm(2, 2);
  weak << 10, 0, 0, 3.4;  // σ along mu_r: 1/3.4 > 1/sqrt(12), the bounds' own spread
  firm << 10, 0, 0, 3.5;
  const IdentifiabilityReport w = AnalyseIdentifiability(weak, {"mu_s", "mu_r"}, {1, 1});
  REQUIRE(w.undetermined.size() == 1);
  CHECK(w.undetermined[0].description.find("mu_r is not determined") != std::string::npos);
  CHECK(w.undetermined[0].sigma_unit == Approx(1 / 3.4));
  CHECK(AnalyseIdentifiability(firm, {"mu_s", "mu_r"}, {1, 1}).Identifiable());
}

// The DEM twin of examples/calibrate_bp_two_targets.json (this session's run, result.json): the
// response surface gave the sliding-friction column 16.6 ± 34.4 and −68.3 ± 53.1, i.e. not
// distinguishable from zero, yet the plain (JᵀJ)⁻¹ made σ(μs) about 0.03 of its range. Weyl's
// inequality (jacobian_svd.h): a singular value no larger than sqrt(Σ σ_ij²) may be noise alone.
TEST_CASE("sensitivities within their own noise do not make a parameter identifiable",
          "[unit][calibrate]") {
  Eigen::MatrixXd j(2, 2), sigma(2, 2);
  j << 16.6, 15.7, -68.3, -23.1;
  sigma << 34.4, 5.95, 53.1, 9.17;
  const double floor = JacobianNoiseFloor(sigma);
  CHECK(floor == Approx(std::sqrt(34.4 * 34.4 + 5.95 * 5.95 + 53.1 * 53.1 + 9.17 * 9.17)));

  const ParameterCovariance naive = CovarianceFromJacobian(j, {0.8, 0.45});
  CHECK(std::isfinite(naive.sigma[0]));  // what was reported before the floor
  const ParameterCovariance c = CovarianceFromJacobian(j, {0.8, 0.45}, floor);
  CHECK(c.rank == 1);
  CHECK(std::isinf(c.sigma[0]));
  CHECK(std::isinf(c.sigma[1]));
  const IdentifiabilityReport r = AnalyseIdentifiability(j, {"mu_s", "mu_r"}, {0.8, 0.45}, floor);
  REQUIRE(r.undetermined.size() == 1);
  CHECK(r.undetermined[0].singular_value > 0);  // seen, but not resolved
  CHECK(std::isinf(r.undetermined[0].sigma_unit));
  CHECK(r.undetermined[0].description.find("within the noise") != std::string::npos);

  // The same J measured ten times more precisely is resolved: the floor is not a fixed cut.
  const double precise = JacobianNoiseFloor(sigma / 10);
  CHECK(CovarianceFromJacobian(j, {0.8, 0.45}, precise).rank == 2);
  CHECK(AnalyseIdentifiability(j, {"mu_s", "mu_r"}, {0.8, 0.45}, precise).undetermined.empty());
}
