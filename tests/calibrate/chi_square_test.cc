#include "calibrate/chi_square.h"

#include <catch2/catch.hpp>
#include <cmath>

namespace demcal::calibrate {

// Reference values: the chi-square and normal tables (e.g. Abramowitz & Stegun 1964, Tables
// 26.8 and 26.1): P(χ²_1 > 3.841) = 0.05, P(χ²_10 > 23.209) = 0.01, P(χ²_30 > 50.892) = 0.01.
TEST_CASE("chi-square tail matches the tables", "[unit]") {
  CHECK(ChiSquareSurvival(3.841459, 1) == Approx(0.05).epsilon(1e-5));
  CHECK(ChiSquareSurvival(23.209251, 10) == Approx(0.01).epsilon(1e-5));
  CHECK(ChiSquareSurvival(50.892181, 30) == Approx(0.01).epsilon(1e-5));
  CHECK(ChiSquareSurvival(0, 5) == 1.0);
  // dof = 2: the tail is exp(−x/2) exactly.
  CHECK(ChiSquareSurvival(7.3, 2) == Approx(std::exp(-3.65)).epsilon(1e-10));
}

TEST_CASE("chi-square quantile inverts the tail and the normal quantile is two-sided", "[unit]") {
  CHECK(ChiSquareQuantile(0.99, 10) == Approx(23.209251).epsilon(1e-6));
  CHECK(NormalTwoSidedQuantile(0.05) == Approx(1.959964).epsilon(1e-6));
  CHECK(NormalTwoSidedQuantile(0.01) == Approx(2.575829).epsilon(1e-6));
}

}  // namespace demcal::calibrate
