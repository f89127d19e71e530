#include "objectives/metrics/random_mixture.h"

#include <catch2/catch.hpp>
#include <cmath>

#include "objectives/metrics/coefficient_of_variation.h"

using namespace demcal::objectives;

namespace {

// c4(n): E[sample std] = c4 σ for n normal samples (the small-sample bias of the std).
double C4(int n) {
  return std::sqrt(2.0 / (n - 1)) * std::exp(std::lgamma(n / 2.0) - std::lgamma((n - 1) / 2.0));
}

}  // namespace

TEST_CASE("CoV uses the sample standard deviation (Eq. 5)", "[unit]") {
  const auto stats = CoefficientOfVariation({1.0, 2.0, 3.0});
  REQUIRE(stats);
  CHECK(stats->mean == Approx(2.0));
  CHECK(stats->std_dev == Approx(1.0));  // sqrt(((1)² + 0 + (1)²)/(3 − 1))
  CHECK(stats->cov == Approx(0.5));
  std::string error;
  CHECK_FALSE(CoefficientOfVariation({0.0, 0.0, 0.0}, &error));
  CHECK(error.find("mean") != std::string::npos);
  CHECK_FALSE(CoefficientOfVariation({0.3}, &error));
}

TEST_CASE("Monte Carlo CoV_r matches the analytic random-mixture CoV for equal bins", "[unit]") {
  // Eq. 6: σ_R = sqrt(P(1 − P)/N), so CoV_r = sqrt((1 − P)/(P N)); the mean sample-std CoV of
  // 21 bins is c4(21) ≈ 0.988 of it. Asked: within 5%.
  const int bins = 21;
  for (double p : {0.02, 0.06, 0.3}) {
    for (RandomDraw draw : {RandomDraw::kNormal, RandomDraw::kBinomial}) {
      const double n = 2000;
      std::string error;
      const auto ref = RandomMixtureCoV(p, std::vector<double>(bins, n), {100, 5, draw}, &error);
      INFO("P = " << p << ", draw " << static_cast<int>(draw) << ": " << error);
      REQUIRE(ref);
      const double analytic = AnalyticRandomCoV(p, n);
      CHECK(ref->cov_r == Approx(C4(bins) * analytic).epsilon(0.05));
      CHECK(ref->repetitions_used == 100);
      // The CoV of 21 normal samples spreads by about 1/sqrt(2·20) of itself.
      CHECK(ref->standard_error == Approx(analytic / std::sqrt(40.0) / 10).epsilon(0.3));
    }
  }
}

TEST_CASE("CoV_r is deterministic from the seed and grows in partly filled bins", "[unit]") {
  const std::vector<double> full(21, 500.0);
  std::vector<double> partial = full;
  for (int b = 0; b < 10; ++b) partial[b] = 60;  // corner and edge bins hold fewer granules
  const RandomMixtureOptions options{200, 42, RandomDraw::kNormal};
  const auto a = RandomMixtureCoV(0.1, full, options, nullptr);
  const auto b = RandomMixtureCoV(0.1, full, options, nullptr);
  const auto c = RandomMixtureCoV(0.1, partial, options, nullptr);
  REQUIRE((a && b && c));
  CHECK(a->cov_r == b->cov_r);
  CHECK(c->cov_r > 1.5 * a->cov_r);
}

TEST_CASE("granules per bin follow the filled volume and 0.6 packing", "[unit]") {
  // A bin filled to 0.6 packing with 1.2e-6 m³ of solid holds 2e-6 m³; granules of 1e-9 m³.
  const double filled = FilledVolumeM3(1.2e-6, 0.6);
  CHECK(filled == Approx(2e-6));
  const auto n = GrainsPerBin({filled, filled / 4}, 1e-9, 0.6);
  CHECK(n[0] == Approx(1200));
  CHECK(n[1] == Approx(300));
}

TEST_CASE("bad random-mixture input is refused without NaN", "[unit]") {
  std::string error;
  CHECK_FALSE(RandomMixtureCoV(0.0, {10, 10}, {}, &error));
  CHECK(error.find("(0, 1)") != std::string::npos);
  CHECK_FALSE(RandomMixtureCoV(0.2, {10, 0}, {}, &error));
  CHECK_FALSE(RandomMixtureCoV(0.2, {10}, {}, &error));
  CHECK_FALSE(RandomMixtureCoV(0.2, {10, 10}, {1, 1, RandomDraw::kNormal}, &error));
  CHECK(error.find("repetitions") != std::string::npos);
}
