#pragma once
// Coefficient of variation of sample concentrations, Alizadeh et al. 2018 Eq. 5: CoV = σ/μ.
// σ is the SAMPLE standard deviation (divisor n − 1), as in docs/physics.md §5.2 where the mean is
// estimated from the same samples; the random-mixture reference (random_mixture.h) uses this same
// function, so the bias of σ cancels in S_n = CoV_m/CoV_r (Eq. 7).
#include <optional>
#include <string>
#include <vector>

namespace demcal::objectives {

struct CovStats {
  double mean = 0;
  double std_dev = 0;  // sample standard deviation (n − 1)
  double cov = 0;      // std_dev / mean
};

// Needs at least two values and a positive mean; otherwise nullopt and a message (never NaN).
std::optional<CovStats> CoefficientOfVariation(const std::vector<double>& values,
                                               std::string* error = nullptr);

}  // namespace demcal::objectives
