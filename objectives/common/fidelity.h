#pragma once
// Fidelity: how far a virtual experiment departs from the real particles to run faster, and the
// rules that keep its physics comparable (docs/physics.md §6, paper section 2.5.1):
//   * size coarse-graining: every particle diameter × size_scale (all species together, so size
//     ratios and mass fractions are kept; the geometry of the test is not scaled);
//   * stiffness reduction: every material's Young's modulus × stiffness_scale;
//   * Γ carried by the Cohesion number Coh = (1/(ρ g)) [Γ⁵/(E*² R*⁸)]^{1/3} (Behjani et al.
//     2017, used by the paper): Coh fixed ⇒ Γ' = Γ (E*'/E*)^{2/5} (R*'/R*)^{8/5};
//   * sjkr's k carried at constant cohesive-to-weight ratio: k' = k (E*'/E*)^{2/3} (R'/R)^{1/3}.
// The fidelity is written into every experiment output.
//
// Usage:
//   Fidelity f = DefaultCalibrationFidelity();
//   ApplyFidelity(f, &scene);  // before geometry that depends on particle size is built
#include <string>

#include "core/scene/scene.h"

namespace demcal::objectives {

struct Fidelity {
  std::string name = "full";
  // Allowed ranges: objectives/common/input_limits.h (kSizeScale, kStiffnessScale, ...).
  double size_scale = 1;         // ≥ 1 (coarse-graining)
  double stiffness_scale = 1;    // ≤ 1 (softer than real)
  double rayleigh_fraction = 0.2;  // Δt as a fraction of the Rayleigh time
  bool IsValid(std::string* error) const;
};

// The fidelity calibrations run at by default: spheres 3× larger, 100× softer.
Fidelity DefaultCalibrationFidelity();
// A coarse, fast preview (--quick).
Fidelity QuickFidelity();

// Cohesion number of a contact (dimensionless): Γ in J/m², E* in Pa, R* in m, ρ in kg/m³.
double CohesionNumber(double gamma_J_m2, double effective_youngs_Pa, double effective_radius_m,
                      double density_kg_m3, double gravity_m_s2);
// The Γ that gives Cohesion number `coh` for the same contact.
double GammaForCohesionNumber(double coh, double effective_youngs_Pa, double effective_radius_m,
                              double density_kg_m3, double gravity_m_s2);
// Γ at constant Cohesion number (and density) after E* × stiffness_ratio, R* × size_ratio.
double ScaleGammaAtConstantCohesion(double gamma_J_m2, double stiffness_ratio, double size_ratio);
// sjkr's cohesion energy density k at constant cohesive-to-weight ratio after the same scaling:
// the cohesion k·π a² ≈ 2πkR*δ at the overlap δ ∝ (W / (E*√R*))^{2/3} a grain's weight W ∝ ρgR³
// makes is a fraction ∝ k / (E*^{2/3} R^{1/3} (ρg)^{1/3}) of W, so k ∝ E*^{2/3} R^{1/3}
// (docs/physics.md §6).
double ScaleSjkrAtConstantBond(double k_J_m3, double stiffness_ratio, double size_ratio);

// Scales the species sizes (and explicit particle diameters), every material's Young's modulus
// and every pair's Γ and k of `scene`, and sets its time-step fraction. Geometry is left alone.
void ApplyFidelity(const Fidelity& fidelity, core::Scene* scene);

}  // namespace demcal::objectives
