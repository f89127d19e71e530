// "Within noise" over several targets (TrialResult::WithinNoise, calibrate/optimiser.h): the
// joint 1σ region, Σ r² / (1 + noise²) ≤ χ²_m(68.27 %), which is the per-target 1σ rule for one
// target and keeps its confidence for many.
#include <catch2/catch.hpp>
#include <cmath>
#include <random>

#include "calibrate/chi_square.h"
#include "calibrate/optimiser.h"

namespace demcal::calibrate {

namespace {
TrialResult Trial(std::vector<double> residuals, std::vector<double> noise = {}) {
  if (noise.empty()) noise.assign(residuals.size(), 0.0);
  return {true, std::move(residuals), std::move(noise)};
}
}  // namespace

TEST_CASE("within noise: one target keeps the 1 sigma rule", "[unit]") {
  CHECK(Trial({0.999}).WithinNoise());
  CHECK_FALSE(Trial({1.001}).WithinNoise());
  CHECK(Trial({1.4}, {1.0}).WithinNoise());  // 1.4 ≤ sqrt(1 + 1)
  CHECK_FALSE(Trial({1.42}, {1.0}).WithinNoise());
}

TEST_CASE("within noise: several targets are judged jointly at the same confidence", "[unit]") {
  // χ²_2 at 68.27 % = −2 ln(1 − 0.6827) = 2.296 (the chi-square with 2 dof is exponential).
  CHECK(ChiSquareQuantile(kWithinNoiseProbability, 2) == Approx(-2 * std::log(1 - kWithinNoiseProbability)).epsilon(1e-9));
  CHECK(Trial({1.2, 0.1}).WithinNoise());        // 1.45: one target just outside its own 1σ
  CHECK_FALSE(Trial({1.6, 0.0}).WithinNoise());  // 2.56
  CHECK_FALSE(Trial({1.2, 0.1}, {2.0, 0.0}).WithinNoise());  // jointly fine, but too noisy
  CHECK(Trial({1.2, 0.1}, {2.0, 0.0}).Inconclusive());
  // The true parameters (residuals standard normal) match with probability 68 % whatever the
  // number of targets; the per-target rule would give 0.68^6 = 10 % for six.
  std::mt19937_64 rng(7);
  std::normal_distribution<double> z;
  for (int m : {1, 2, 6, 12}) {
    int matched = 0;
    const int trials = 20000;
    for (int i = 0; i < trials; ++i) {
      std::vector<double> r(m);
      for (double& x : r) x = z(rng);
      matched += Trial(r).WithinNoise();
    }
    INFO(m << " targets: " << matched << " of " << trials);
    CHECK(std::abs(matched / double(trials) - kWithinNoiseProbability) < 0.015);  // 4.5 binomial σ
  }
}

TEST_CASE("settled: a search for n parameters stops inside their joint 1 sigma region", "[unit]") {
  // Six residuals of 1.0: Σ = 6 ≤ χ²_6(68 %) = 7.04, a match; but for one parameter the 1σ
  // region is χ² − χ²_min ≤ 1, and with χ²_min ≥ 0 only Σ ≤ 1 proves a point lies inside it.
  const TrialResult six = Trial({1, 1, 1, 1, 1, 1});
  CHECK(six.WithinNoise());
  CHECK_FALSE(six.Settled(1));
  CHECK_FALSE(six.Settled(3));  // χ²_3(68 %) = 3.53
  CHECK(six.Settled(6));        // as many parameters as targets: the match itself
  CHECK(six.Settled(9));
  CHECK(Trial({0.9, 0.3, 0.2}).Settled(1));     // 0.94 ≤ 1
  CHECK_FALSE(Trial({2, 0, 0}, {2, 0, 0}).Settled(3));  // too noisy to settle anything
}

}  // namespace demcal::calibrate
