#pragma once
// Γ of a coated–uncoated pair (paper section 2.5.3, step 4 of its pipeline): half of the
// coated–coated Γ (one adhesive surface instead of two, JKR), carried from the coated pair's
// reduced radius to the dissimilar pair's at constant Cohesion number, Coh ∝ (Γ⁵/R*⁸)^{1/3}:
//   Γ_pair = (Γ_coated / 2) · (R*_pair / R*_coated)^{8/5}.
// Note on the paper's Eq. (4): as typeset it reads Γ₂ = Γ₁ (R₁*/R₂*)^{8/5}, which would make Γ
// fall as R* grows, against both the Cohesion number and the paper's own results (EP–TAED,
// the larger pair, gets the larger Γ: 0.060 vs 0.037 J/m²). The rule here follows the Cohesion
// number. Like the paper's Cohesion number evaluation (section 2.5.2), R*_coated is taken as
// the coated granule's radius itself (see the test, which reproduces 0.037 and 0.060 J/m²).
//
//   double g = DissimilarPairGamma(0.25, 325e-6, ReducedRadius(325e-6, 231e-6));
#include <cmath>

namespace demcal::calibrate {

inline double ReducedRadius(double r1_m, double r2_m) { return r1_m * r2_m / (r1_m + r2_m); }

inline double DissimilarPairGamma(double gamma_coated_J_m2, double coated_reduced_radius_m,
                                  double pair_reduced_radius_m) {
  return 0.5 * gamma_coated_J_m2 * std::pow(pair_reduced_radius_m / coated_reduced_radius_m, 1.6);
}

}  // namespace demcal::calibrate
