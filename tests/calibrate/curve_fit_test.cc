#include "calibrate/curve_fit.h"

#include <catch2/catch.hpp>
#include <cmath>

using namespace demcal::calibrate;

TEST_CASE("curve fit: a weighted line matches the closed-form least squares and its covariance",
          "[unit]") {
  // Closed form of weighted linear regression (e.g. Press et al., Numerical Recipes §15.2):
  // S = Σ1/σ², Sx = Σx/σ², Sxx = Σx²/σ², Δ = S·Sxx − Sx²; var(c0) = Sxx/Δ, var(c1) = S/Δ,
  // cov(c0, c1) = −Sx/Δ.
  std::vector<CurvePoint> pts = {{0.5, 0.05, 0.004}, {1.5, 0.14, 0.01}, {2.5, 0.24, 0.02},
                                 {3.5, 0.36, 0.03}};
  double S = 0, Sx = 0, Sxx = 0, Sy = 0, Sxy = 0;
  for (const auto& p : pts) {
    double w = 1 / (p.sigma * p.sigma);
    S += w; Sx += w * p.x; Sxx += w * p.x * p.x; Sy += w * p.y; Sxy += w * p.x * p.y;
  }
  double delta = S * Sxx - Sx * Sx;
  CurveFitResult fit;
  std::string error;
  REQUIRE(FitCurve(CurveForm::kLinear, pts, &fit, &error));
  CHECK(fit.coefficients[0] == Approx((Sxx * Sy - Sx * Sxy) / delta).epsilon(1e-8));
  CHECK(fit.coefficients[1] == Approx((S * Sxy - Sx * Sy) / delta).epsilon(1e-8));
  REQUIRE(fit.covariance.size() == 2);
  CHECK(fit.covariance[0][0] == Approx(Sxx / delta).epsilon(1e-6));
  CHECK(fit.covariance[1][1] == Approx(S / delta).epsilon(1e-6));
  CHECK(fit.covariance[0][1] == Approx(-Sx / delta).epsilon(1e-6));
  CHECK(fit.dof == 2);
  // The band at x is sqrt(var c0 + 2x cov + x² var c1).
  double x = 2.0;
  CHECK(fit.StandardError(x) ==
        Approx(std::sqrt((Sxx - 2 * x * Sx + x * x * S) / delta)).epsilon(1e-6));
}

TEST_CASE("curve fit: a power law through exact points is recovered", "[unit]") {
  std::vector<CurvePoint> pts;
  for (double x : {0.5, 1.5, 2.5, 3.5}) pts.push_back({x, 0.08 * std::pow(x, 1.3), 0.001});
  CurveFitResult fit;
  std::string error;
  REQUIRE(FitCurve(CurveForm::kPowerLaw, pts, &fit, &error));
  CHECK(fit.coefficients[0] == Approx(0.08).epsilon(1e-6));
  CHECK(fit.coefficients[1] == Approx(1.3).epsilon(1e-6));
  CHECK(fit.chi2 < 1e-8);
}

TEST_CASE("curve fit: through the origin, one coefficient", "[unit]") {
  CurveFitResult fit;
  std::string error;
  REQUIRE(FitCurve(CurveForm::kLinearThroughOrigin, {{1, 0.1, 0.01}, {2, 0.2, 0.01}}, &fit, &error));
  CHECK(fit.coefficients[0] == Approx(0.1));
  // var(c0) = 1/Σ(x²/σ²) = 1/(5e4)
  CHECK(fit.covariance[0][0] == Approx(1 / 5e4).epsilon(1e-6));
}

TEST_CASE("curve fit refuses too few points, bad sigma and x <= 0 for a power law", "[unit]") {
  CurveFitResult fit;
  std::string error;
  CHECK_FALSE(FitCurve(CurveForm::kLinear, {{1, 1, 0.1}}, &fit, &error));
  CHECK(error.find("1 points for 2 coefficients") != std::string::npos);
  CHECK_FALSE(FitCurve(CurveForm::kLinear, {{1, 1, 0}, {2, 2, 0.1}}, &fit, &error));
  CHECK_FALSE(FitCurve(CurveForm::kPowerLaw, {{0, 1, 0.1}, {2, 2, 0.1}}, &fit, &error));
  CHECK(error.find("x <= 0") != std::string::npos);
}
