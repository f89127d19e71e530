// Two candidates compared under one floor (BicGap, evidence.h): each candidate's ΔBIC uses the
// floor of its own fit, so two fits alike in their residuals can look far apart by ΔBIC alone.
#include <catch2/catch.hpp>
#include <cmath>

#include "diagnose/ranking/discrepancy_floor.h"
#include "diagnose/ranking/evidence.h"

namespace demcal::diagnose {
namespace {

// n = 12 observations, single-run scatter q = 1 each, one fitted base parameter, k = 1.
Evidence FitWithResidual(double residual) {
  const Eigen::VectorXd base = Eigen::VectorXd::Constant(12, 5.0);
  return EvidenceWithFloor(base, Eigen::VectorXd::Constant(12, residual),
                           Eigen::VectorXd::Ones(12), 1, 1, 0.01);
}

}  // namespace

TEST_CASE("BicGap: two fits alike are not told apart though their own floors split them",
          "[unit]") {
  // Residuals 1.0 and 1.1 everywhere: χ² 12 and 14.5 at σ, both above the 10 degrees of
  // freedom, so each fit gets a floor (φ² = 0.2 and 0.452), and the base χ² (300 at σ) divided by
  // a smaller (1 + φ²) makes the better fit's ΔBIC about 43 lower.
  const Evidence a = FitWithResidual(1.0), b = FitWithResidual(1.1);
  REQUIRE(a.floor > 0);
  REQUIRE(b.floor > a.floor);
  CHECK(b.delta_bic - a.delta_bic > 40);
  // Under the smaller floor the two differ by their own χ² only: 12/1.2 against 14.52/1.2.
  const Eigen::VectorXd q = Eigen::VectorXd::Ones(12);
  const double expected = FlooredChi2(Eigen::VectorXd::Constant(12, 1.0), q, a.floor) -
                          FlooredChi2(Eigen::VectorXd::Constant(12, 1.1), q, a.floor);
  CHECK(BicGap(a, b) == Approx(expected));
  CHECK(BicGap(a, b) == Approx(10.0 - 14.52 / 1.2).epsilon(1e-3));
  CHECK(BicGap(b, a) == Approx(-BicGap(a, b)));
  CHECK_FALSE(ToldApart(a, b));
}

TEST_CASE("BicGap: a clearly better fit is still told apart", "[unit]") {
  // Residuals 1.0 against 2.0: 10 against 48/1.2 = 40 under the smaller floor.
  const Evidence a = FitWithResidual(1.0), b = FitWithResidual(2.0);
  CHECK(BicGap(a, b) == Approx(10.0 - 40.0).epsilon(1e-3));
  CHECK(ToldApart(a, b));
}

TEST_CASE("BicGap: without residuals it is the ΔBIC difference", "[unit]") {
  const Evidence a = EvidenceOf(300, 12, 1, 12, 0.01), b = EvidenceOf(300, 20, 1, 12, 0.01);
  CHECK(BicGap(a, b) == Approx(a.delta_bic - b.delta_bic));
  CHECK(ToldApart(a, b));
}

}  // namespace demcal::diagnose
