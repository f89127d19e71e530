#include "objectives/metrics/random_mixture.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/math/random.h"
#include "objectives/metrics/coefficient_of_variation.h"

namespace demcal::objectives {
namespace {

// Standard normal by Box–Muller (one of the pair; 1 − u keeps the logarithm finite).
double StandardNormal(core::Rng& rng) {
  const double u = 1.0 - rng.Uniform();
  const double v = rng.Uniform();
  return std::sqrt(-2.0 * std::log(u)) * std::cos(2.0 * std::numbers::pi * v);
}

// Binomial(n, p) for p ≤ 0.5 by inversion, in chunks whose mean is at most 50 so (1 − p)^chunk
// cannot underflow; the cost is about n p uniforms.
int64_t BinomialSmallP(core::Rng& rng, int64_t n, double p) {
  if (p <= 0) return 0;
  const auto chunk = std::max<int64_t>(1, static_cast<int64_t>(50.0 / p));
  int64_t successes = 0;
  for (int64_t done = 0; done < n; done += chunk) {
    const int64_t m = std::min(chunk, n - done);
    double pmf = std::pow(1.0 - p, static_cast<double>(m));
    double cdf = pmf;
    const double u = rng.Uniform();
    int64_t k = 0;
    while (u >= cdf && k < m) {
      pmf *= static_cast<double>(m - k) / static_cast<double>(k + 1) * p / (1.0 - p);
      cdf += pmf;
      ++k;
    }
    successes += k;
  }
  return successes;
}

double DrawFraction(core::Rng& rng, double p, double n, RandomDraw draw) {
  if (draw == RandomDraw::kNormal) return p + std::sqrt(p * (1 - p) / n) * StandardNormal(rng);
  const int64_t trials = std::max<int64_t>(1, std::llround(n));
  const int64_t k =
      p <= 0.5 ? BinomialSmallP(rng, trials, p) : trials - BinomialSmallP(rng, trials, 1 - p);
  return static_cast<double>(k) / static_cast<double>(trials);
}

}  // namespace

bool RandomMixtureOptions::IsValid(std::string* error) const {
  if (repetitions >= 2) return true;
  if (error) *error = "random mixture: repetitions must be >= 2";
  return false;
}

double FilledVolumeM3(double solid_volume_m3, double packing_fraction) {
  return solid_volume_m3 / packing_fraction;
}

std::vector<double> GrainsPerBin(const std::vector<double>& filled_volumes_m3,
                                 double granule_volume_m3, double packing_fraction) {
  std::vector<double> n;
  for (double v : filled_volumes_m3) n.push_back(v * packing_fraction / granule_volume_m3);
  return n;
}

std::optional<RandomMixtureCov> RandomMixtureCoV(double p,
                                                 const std::vector<double>& grains_per_bin,
                                                 const RandomMixtureOptions& options,
                                                 std::string* error) {
  auto fail = [&](const std::string& message) {
    if (error) *error = "random mixture: " + message;
    return std::nullopt;
  };
  if (!options.IsValid(error)) return std::nullopt;
  if (!(p > 0 && p < 1))
    return fail("mean fraction P must lie in (0, 1), got " + std::to_string(p));
  if (grains_per_bin.size() < 2) return fail("needs at least two bins");
  for (double n : grains_per_bin)
    if (!(n > 0) || !std::isfinite(n)) return fail("every bin needs N > 0 grains");
  core::Rng rng(options.seed);
  std::vector<double> covs, fractions(grains_per_bin.size());
  for (int rep = 0; rep < options.repetitions; ++rep) {
    for (size_t b = 0; b < grains_per_bin.size(); ++b)
      fractions[b] = DrawFraction(rng, p, grains_per_bin[b], options.draw);
    if (const auto stats = CoefficientOfVariation(fractions)) covs.push_back(stats->cov);
  }
  if (covs.size() < 2) return fail("too few repetitions with a positive mean fraction");
  const double reps = static_cast<double>(covs.size());
  double sum = 0, squares = 0;
  for (double c : covs) sum += c;
  RandomMixtureCov result;
  result.cov_r = sum / reps;
  for (double c : covs) squares += (c - result.cov_r) * (c - result.cov_r);
  result.standard_error = std::sqrt(squares / (reps - 1) / reps);
  result.repetitions_used = static_cast<int>(covs.size());
  return result;
}

double AnalyticRandomCoV(double p, double grains_per_bin) {
  return std::sqrt((1 - p) / (p * grains_per_bin));
}

}  // namespace demcal::objectives
