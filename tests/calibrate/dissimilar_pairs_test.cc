#include "calibrate/dissimilar_pairs.h"

#include <catch2/catch.hpp>

#include "objectives/common/fidelity.h"

using namespace demcal;

TEST_CASE("dissimilar-pair Γ keeps the Cohesion number of the half-Γ pair", "[unit][calibrate]") {
  const double gamma = 0.25, r_coated = 325e-6, r_pair = calibrate::ReducedRadius(325e-6, 231e-6);
  const double g = calibrate::DissimilarPairGamma(gamma, r_coated, r_pair);
  const double e_star = 1e8, rho = 2320, grav = 9.81;
  CHECK(objectives::CohesionNumber(g, e_star, r_pair, rho, grav) ==
        Approx(objectives::CohesionNumber(0.5 * gamma, e_star, r_coated, rho, grav)).epsilon(1e-12));
  CHECK(calibrate::DissimilarPairGamma(gamma, r_coated, r_coated) == Approx(0.125));
}

// Alizadeh et al. 2018, section 2.5.3: from Γ_EP = 0.250 J/m² (2.5 wt% PEG), EP–BP 0.037 and
// EP–TAED 0.060 J/m², with the "equivalent volume radii" of the (clumped) BP and TAED particles,
// which the paper does not list. With the sieve-cut means (Table 1: EP 600–700, BP 425–500, TAED
// 850–1000 µm) the rule gives 0.031 and 0.053 J/m²; the paper's values follow if the
// equivalent-volume diameters are 570 µm (BP) and 1.12 mm (TAED), ≈ 1.2× the sieve means, as for
// elongated grains that pass a sieve by their smaller dimension. So: within 20% from sieve
// sizes, and the ratio EP–TAED / EP–BP (1.62 in the paper) within 10%.
TEST_CASE("dissimilar-pair Γ reproduces the paper's EP-BP and EP-TAED values", "[physics][calibrate]") {
  const double r_ep = 0.5 * 650e-6, r_bp = 0.5 * 462.5e-6, r_taed = 0.5 * 925e-6;
  const double g_bp = calibrate::DissimilarPairGamma(0.25, r_ep, calibrate::ReducedRadius(r_ep, r_bp));
  const double g_taed = calibrate::DissimilarPairGamma(0.25, r_ep, calibrate::ReducedRadius(r_ep, r_taed));
  CHECK(g_bp == Approx(0.037).epsilon(0.20));
  CHECK(g_taed == Approx(0.060).epsilon(0.20));
  CHECK(g_taed / g_bp == Approx(0.060 / 0.037).epsilon(0.10));
}
