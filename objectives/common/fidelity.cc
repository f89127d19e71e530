#include "objectives/common/fidelity.h"

#include <cmath>
#include <sstream>

#include "objectives/common/input_limits.h"

namespace demcal::objectives {

bool Fidelity::IsValid(std::string* error) const {
  std::ostringstream os;
  if (!limits::kSizeScale.Contains(size_scale))
    os << "fidelity.size_scale = " << size_scale << " is outside the allowed range "
       << limits::kSizeScale.Text();
  else if (!limits::kStiffnessScale.Contains(stiffness_scale))
    os << "fidelity.stiffness_scale = " << stiffness_scale << " is outside the allowed range "
       << limits::kStiffnessScale.Text();
  else if (!limits::kRayleighFraction.Contains(rayleigh_fraction))
    os << "fidelity.rayleigh_fraction = " << rayleigh_fraction << " is outside the allowed range "
       << limits::kRayleighFraction.Text();
  if (os.str().empty()) return true;
  if (error) *error = os.str();
  return false;
}

Fidelity DefaultCalibrationFidelity() { return {"calibration", 3.0, 0.01, 0.2}; }

Fidelity QuickFidelity() { return {"quick", 5.0, 0.01, 0.25}; }

double CohesionNumber(double gamma_J_m2, double effective_youngs_Pa, double effective_radius_m,
                      double density_kg_m3, double gravity_m_s2) {
  const double r = effective_radius_m;
  return std::cbrt(std::pow(gamma_J_m2, 5) /
                   (effective_youngs_Pa * effective_youngs_Pa * std::pow(r, 8))) /
         (density_kg_m3 * gravity_m_s2);
}

double GammaForCohesionNumber(double coh, double effective_youngs_Pa, double effective_radius_m,
                              double density_kg_m3, double gravity_m_s2) {
  // Coh ρ g = (Γ⁵ / (E*² R*⁸))^{1/3}  ⇒  Γ = ((Coh ρ g)³ E*² R*⁸)^{1/5}
  const double a = coh * density_kg_m3 * gravity_m_s2;
  return std::pow(a * a * a * effective_youngs_Pa * effective_youngs_Pa *
                      std::pow(effective_radius_m, 8),
                  0.2);
}

double ScaleGammaAtConstantCohesion(double gamma_J_m2, double stiffness_ratio, double size_ratio) {
  return gamma_J_m2 * std::pow(stiffness_ratio, 0.4) * std::pow(size_ratio, 1.6);
}

double ScaleSjkrAtConstantBond(double k_J_m3, double stiffness_ratio, double size_ratio) {
  return k_J_m3 * std::cbrt(stiffness_ratio * stiffness_ratio * size_ratio);
}

namespace {

void ScaleSizes(double s, core::SizeDistribution* size) {
  size->diameter_m *= s;
  size->min_diameter_m *= s;
  size->max_diameter_m *= s;
  for (double& d : size->table_diameter_m) d *= s;
}

}  // namespace

void ApplyFidelity(const Fidelity& fidelity, core::Scene* scene) {
  const double s = fidelity.size_scale, k = fidelity.stiffness_scale;
  for (core::Species& sp : scene->species) ScaleSizes(s, &sp.size);
  for (core::ParticleSpec& p : scene->particles) p.diameter_m *= s;
  for (core::Material& m : scene->materials) m.youngs_modulus_Pa *= k;
  // Every E scales by k, so every E* does; every R* of a particle pair scales by s.
  for (core::PairParameters& pair : scene->pair_parameters) {
    pair.interfacial_energy_J_m2 = ScaleGammaAtConstantCohesion(pair.interfacial_energy_J_m2, k, s);
    pair.cohesion_energy_density_J_m3 =
        ScaleSjkrAtConstantBond(pair.cohesion_energy_density_J_m3, k, s);
  }
  scene->time.rayleigh_fraction = fidelity.rayleigh_fraction;
}

}  // namespace demcal::objectives
