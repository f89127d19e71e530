#include "objectives/metrics/coefficient_of_variation.h"

#include <cmath>

namespace demcal::objectives {

std::optional<CovStats> CoefficientOfVariation(const std::vector<double>& values,
                                               std::string* error) {
  auto fail = [&](const std::string& message) {
    if (error) *error = "CoV: " + message;
    return std::nullopt;
  };
  if (values.size() < 2)
    return fail("needs at least two bins, got " + std::to_string(values.size()));
  double sum = 0;
  for (double v : values) sum += v;
  const double n = static_cast<double>(values.size());
  CovStats stats;
  stats.mean = sum / n;
  if (!(stats.mean > 0) || !std::isfinite(stats.mean)) return fail("the mean concentration is 0");
  double squares = 0;
  for (double v : values) squares += (v - stats.mean) * (v - stats.mean);
  stats.std_dev = std::sqrt(squares / (n - 1));
  stats.cov = stats.std_dev / stats.mean;
  return stats;
}

}  // namespace demcal::objectives
