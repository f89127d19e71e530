#pragma once
// Beverloo's law for the mass flow of coarse cohesionless grains through a circular orifice,
//   W = C ρ_b √g (D − k d)^{5/2}
// (Beverloo, Leniger & van de Velde 1961, Chem. Eng. Sci. 15:260; C ≈ 0.55–0.65, k ≈ 1–2; it
// validates the funnel-discharge experiment). FitBeverloo fits C and k to flows measured at several
// orifice diameters D: k by a 1-D minimisation over 0 ≤ k < min D/d, C in closed form for each k.
// Residuals are relative, (W_fit − W)/W, so every orifice counts alike whatever its flow.
// Pure function, SI units, thread-safe.
//
//   BeverlooFit f = FitBeverloo({{0.008, 0.011}, {0.012, 0.034}, {0.016, 0.071}},
//                               /*bulk_density_kg_m3=*/1500, /*particle_diameter_m=*/0.002, 9.81);
//   if (f.ok) std::printf("C = %.3f, k = %.2f\n", f.C, f.k);
#include <string>
#include <vector>

namespace demcal::objectives {

struct BeverlooPoint {
  double orifice_diameter_m = 0;
  double mass_flow_kg_s = 0;
};

struct BeverlooFit {
  bool ok = false;
  std::string message = "not fitted";
  double C = 0;                      // discharge coefficient (dimensionless)
  double k = 0;                      // empty-annulus coefficient (dimensionless)
  double rms_relative_residual = 0;  // √(mean ((W_fit − W)/W)²)
};

// The law itself: mass flow in kg/s; 0 when D ≤ k d (no flow through a blocked orifice).
double BeverlooMassFlow(double C, double k, double orifice_diameter_m, double bulk_density_kg_m3,
                        double particle_diameter_m, double g_m_s2);

// Needs at least 3 different orifice sizes, all larger than the particle diameter, positive
// flows and material values. Refuses (ok = false) when the best k leaves the smallest orifice an
// open width D − k d below 1% of a grain diameter, i.e. the data ask for D ≤ k d there.
BeverlooFit FitBeverloo(const std::vector<BeverlooPoint>& points, double bulk_density_kg_m3,
                        double particle_diameter_m, double g_m_s2);

}  // namespace demcal::objectives
