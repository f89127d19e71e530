#include "calibrate/cohesion_scaling.h"

#include <cmath>

#include "objectives/common/fidelity.h"

namespace demcal::calibrate {
namespace {

bool Positive(double v, const char* name, double hi, std::string* error) {
  if (std::isfinite(v) && v > 0 && v <= hi) return true;
  if (error) *error = std::string(name) + " must be in (0, " + std::to_string(hi) + "]";
  return false;
}

}  // namespace

bool CohesionInputs::IsValid(std::string* error) const {
  if (!Positive(gamma_J_m2, "gamma_J_m2", 100, error) ||
      !Positive(youngs_real_Pa, "youngs_real_Pa", 1e13, error) ||
      !Positive(youngs_sim_Pa, "youngs_sim_Pa", 1e13, error) ||
      !Positive(radius_m, "radius_m", 1, error) ||
      !Positive(density_kg_m3, "density_kg_m3", 1e5, error) ||
      !Positive(gravity_m_s2, "gravity_m_s2", 1e3, error) ||
      !Positive(reference_gamma_sim_J_m2, "reference_gamma_sim_J_m2", 100, error)) {
    return false;
  }
  if (!(poisson_ratio > -1 && poisson_ratio < 0.5)) {
    if (error) *error = "poisson_ratio must be in (-1, 0.5)";
    return false;
  }
  return true;
}

CohesionReport EvaluateCohesion(const CohesionInputs& in) {
  CohesionReport r;
  const double factor = 1 / (2 * (1 - in.poisson_ratio * in.poisson_ratio));
  r.effective_youngs_real_Pa = in.youngs_real_Pa * factor;
  r.effective_youngs_sim_Pa = in.youngs_sim_Pa * factor;
  r.effective_radius_m = in.radius_m;
  r.cohesion_number = objectives::CohesionNumber(in.gamma_J_m2, r.effective_youngs_real_Pa,
                                                 in.radius_m, in.density_kg_m3, in.gravity_m_s2);
  r.cohesion_number_pair_radius = objectives::CohesionNumber(
      in.gamma_J_m2, r.effective_youngs_real_Pa, in.radius_m / 2, in.density_kg_m3,
      in.gravity_m_s2);
  r.gamma_sim_J_m2 =
      objectives::GammaForCohesionNumber(r.cohesion_number, r.effective_youngs_sim_Pa, in.radius_m,
                                         in.density_kg_m3, in.gravity_m_s2);
  // Γ ∝ E*^{2/5} at constant Coh  ⇒  E_sim = E_real (Γ_ref/Γ)^{5/2}.
  r.youngs_sim_for_reference_Pa =
      in.youngs_real_Pa * std::pow(in.reference_gamma_sim_J_m2 / in.gamma_J_m2, 2.5);
  return r;
}

}  // namespace demcal::calibrate
