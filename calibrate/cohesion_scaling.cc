#include "calibrate/cohesion_scaling.h"

#include <cmath>

#include "objectives/common/fidelity.h"
#include "objectives/common/input_limits.h"

namespace demcal::calibrate {
namespace {

namespace limits = objectives::limits;

// Reads as the command line's check does (Limit::Text, 6 significant digits).
bool Within(double v, const limits::Limit& limit, const char* name, std::string* error) {
  if (limit.Contains(v)) return true;
  if (error) *error = std::string(name) + " must be in " + limit.Text();
  return false;
}

}  // namespace

bool CohesionInputs::IsValid(std::string* error) const {
  return Within(gamma_J_m2, limits::kCohesionGamma, "gamma_J_m2", error) &&
         Within(youngs_real_Pa, limits::kCohesionYoungs, "youngs_real_Pa", error) &&
         Within(youngs_sim_Pa, limits::kCohesionYoungs, "youngs_sim_Pa", error) &&
         Within(radius_m, limits::kCohesionRadius, "radius_m", error) &&
         Within(density_kg_m3, limits::kCohesionDensity, "density_kg_m3", error) &&
         Within(gravity_m_s2, limits::kCohesionGravity, "gravity_m_s2", error) &&
         Within(reference_gamma_sim_J_m2, limits::kCohesionGamma, "reference_gamma_sim_J_m2",
                error) &&
         Within(poisson_ratio, limits::kCohesionPoisson, "poisson_ratio", error);
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
