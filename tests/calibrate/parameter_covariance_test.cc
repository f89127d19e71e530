// Covariance from the sensitivity matrix: (JᵀJ)⁻¹ when J has full rank, converted to SI
// (linear and log-scale parameters); +∞ and "not identifiable" when it has not.
#include "calibrate/parameter_covariance.h"

#include <catch2/catch.hpp>
#include <cmath>

using namespace demcal::calibrate;

TEST_CASE("covariance of a full-rank J is (J^T J)^-1, in SI", "[unit][calibrate]") {
  Eigen::MatrixXd j(3, 2);
  j << 6, 2, -1, 5, 2, 2;
  const Eigen::MatrixXd expected = (j.transpose() * j).inverse();
  const ParameterCovariance c = CovarianceFromJacobian(j, {0.5, 2.0});
  CHECK(c.rank == 2);
  for (int k = 0; k < 2; ++k) {
    CHECK(c.sigma_unit[k] == Approx(std::sqrt(expected(k, k))));
    CHECK(c.identifiable[k]);
  }
  CHECK(c.sigma[0] == Approx(0.5 * std::sqrt(expected(0, 0))));
  CHECK(c.sigma[1] == Approx(2.0 * std::sqrt(expected(1, 1))));
  CHECK(c.correlation(0, 1) == Approx(expected(0, 1) / std::sqrt(expected(0, 0) * expected(1, 1))));
  CHECK(c.correlation(0, 0) == Approx(1.0));
  CHECK(c.covariance(0, 1) == Approx(expected(0, 1) * 0.5 * 2.0));
}

TEST_CASE("unit-to-SI scale respects log-scale parameters", "[unit][calibrate]") {
  ParameterSpace space;
  space.parameters.push_back({"mu_s", PairProperty::kSlidingFriction, 0, 0, 0.1, 0.9, 0.5});
  space.parameters.push_back(
      {"gamma", PairProperty::kInterfacialEnergy, 0, 0, 1e-3, 1.0, 0.01, true});
  const std::vector<double> u{0.3, 0.4};
  const std::vector<double> scale = SiPerUnit(space, u);
  const double h = 1e-6;
  for (int k = 0; k < 2; ++k) {
    std::vector<double> up = u, down = u;
    up[k] += h, down[k] -= h;
    const double numeric = (space.FromUnit(up)[k] - space.FromUnit(down)[k]) / (2 * h);
    CHECK(scale[k] == Approx(numeric).epsilon(1e-5));
  }
}

TEST_CASE("a rank-deficient J gives no finite sigma", "[unit][calibrate]") {
  Eigen::MatrixXd j(2, 3);  // the third parameter is seen by nothing; rows proportional in 0–1
  j << 4, 2, 0, 8, 4, 0;
  const ParameterCovariance c = CovarianceFromJacobian(j, {1, 1, 1});
  CHECK(c.rank == 1);
  for (int k = 0; k < 3; ++k) {
    CHECK(std::isinf(c.sigma[k]));
    CHECK_FALSE(c.identifiable[k]);
  }
  CHECK(std::isnan(c.correlation(0, 1)));
  CHECK(c.note.find("rank-deficient") != std::string::npos);

  Eigen::MatrixXd partial(2, 2);  // only the second parameter is blind
  partial << 6, 0, -3, 0;
  const ParameterCovariance p = CovarianceFromJacobian(partial, {1, 1});
  CHECK(p.sigma_unit[0] == Approx(1 / std::sqrt(45.0)));
  CHECK(p.identifiable[0]);
  CHECK(std::isinf(p.sigma[1]));
}

TEST_CASE("a finite sigma wider than the bounds is not identifiable", "[unit][calibrate]") {
  Eigen::MatrixXd j(2, 2);
  j << 20, 0, 0, 2;  // σ_unit = 0.05 and 0.5 > 1/sqrt(12)
  const ParameterCovariance c = CovarianceFromJacobian(j, {1, 1});
  CHECK(c.identifiable[0]);
  CHECK(std::isfinite(c.sigma[1]));
  CHECK_FALSE(c.identifiable[1]);
}
