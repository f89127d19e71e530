#include "objectives/metrics/beverloo.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <random>

using namespace demcal::objectives;

namespace {

// Typical values (Beverloo et al. 1961: C ≈ 0.58, k ≈ 1.5) for 2 mm grains of bulk density 1500.
constexpr double kC = 0.58, kK = 1.5, kDensity = 1500, kD = 0.002, kG = 9.81;
const std::vector<double> kOrifices = {0.008, 0.012, 0.016, 0.024};

std::vector<BeverlooPoint> Data(double relative_noise, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> noise(0, relative_noise);
  std::vector<BeverlooPoint> points;
  for (double orifice : kOrifices)
    points.push_back({orifice, BeverlooMassFlow(kC, kK, orifice, kDensity, kD, kG) *
                                   (1 + (relative_noise > 0 ? noise(rng) : 0))});
  return points;
}

// Linearised standard errors of (ln C, k) for relative noise σ: ln W = ln C + … + 2.5 ln(D − k d),
// so the Jacobian rows are [1, −2.5 d/(D − k d)] and the covariance is σ² (JᵀJ)⁻¹.
void StandardErrors(double sigma, double* se_ln_c, double* se_k) {
  double n = 0, sj = 0, sjj = 0;
  for (double orifice : kOrifices) {
    const double j = -2.5 * kD / (orifice - kK * kD);
    n += 1, sj += j, sjj += j * j;
  }
  const double det = n * sjj - sj * sj;
  *se_ln_c = sigma * std::sqrt(sjj / det);
  *se_k = sigma * std::sqrt(n / det);
}

}  // namespace

TEST_CASE("Beverloo: exact data give back the C and k that made them", "[unit]") {
  const BeverlooFit fit = FitBeverloo(Data(0, 1), kDensity, kD, kG);
  INFO(fit.message);
  REQUIRE(fit.ok);
  CHECK(fit.C == Approx(kC).epsilon(1e-6));
  CHECK(fit.k == Approx(kK).epsilon(1e-6));
  CHECK(fit.rms_relative_residual < 1e-6);
}

TEST_CASE("Beverloo: 2% noise recovers C and k within their standard errors", "[unit]") {
  double se_ln_c = 0, se_k = 0;
  StandardErrors(0.02, &se_ln_c, &se_k);
  for (unsigned seed : {1u, 2u, 3u}) {
    const BeverlooFit fit = FitBeverloo(Data(0.02, seed), kDensity, kD, kG);
    REQUIRE(fit.ok);
    CHECK(std::log(fit.C / kC) == Approx(0).margin(4 * se_ln_c));
    CHECK(fit.k == Approx(kK).margin(4 * se_k));
    CHECK(fit.rms_relative_residual > 0);
    CHECK(fit.rms_relative_residual < 0.02 * 3);
  }
}

TEST_CASE("Beverloo: too few sizes or blocked orifices are refused", "[unit]") {
  std::vector<BeverlooPoint> data = Data(0, 1);
  const std::vector<BeverlooPoint> two(data.begin(), data.begin() + 2);
  BeverlooFit fit = FitBeverloo(two, kDensity, kD, kG);
  CHECK_FALSE(fit.ok);
  CHECK(fit.message.find("3 different orifice sizes") != std::string::npos);
  // Four points but only two sizes.
  fit = FitBeverloo({data[0], data[0], data[1], data[1]}, kDensity, kD, kG);
  CHECK_FALSE(fit.ok);
  // An orifice no wider than a grain.
  data.push_back({kD, 1e-4});
  CHECK_FALSE(FitBeverloo(data, kDensity, kD, kG).ok);
  // The smallest orifice flows far less than any D − k d > 0 allows: the fit asks for D ≤ k d.
  std::vector<BeverlooPoint> jamming = Data(0, 1);
  jamming[0].mass_flow_kg_s *= 1e-12;
  fit = FitBeverloo(jamming, kDensity, kD, kG);
  CHECK_FALSE(fit.ok);
  CHECK(fit.message.find("D <= k d") != std::string::npos);
  CHECK(std::isfinite(fit.C));
  CHECK_FALSE(FitBeverloo(Data(0, 1), -1, kD, kG).ok);
}
