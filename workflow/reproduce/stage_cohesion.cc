// Stage 2, Cohesion number (paper section 2.5.2, Eq. 1–3): Coh of the coated species at its real
// stiffness and the Γ that keeps it at the simulation stiffness (calibrate/cohesion_scaling.h,
// where the R* and E* convention is stated). Pure arithmetic: no simulation.
#include <cmath>
#include <cstdio>

#include "calibrate/cohesion_scaling.h"
#include "workflow/reproduce/cohesion_json.h"
#include "workflow/reproduce/stages.h"

namespace demcal::workflow {

bool RunCohesionStage(ReproduceContext& ctx, nlohmann::json* result, std::string* error) {
  const calibrate::CohesionInputs& in = ctx.workflow->cohesion;
  if (!in.IsValid(error)) {
    *error = ctx.workflow->source + ": cohesion: " + *error;
    return false;
  }
  const calibrate::CohesionReport r = calibrate::EvaluateCohesion(in);
  char why[400];
  std::snprintf(why, sizeof(why),
                "Γ ∝ E*^(2/5) at constant Coh: %.3g J/m² at E = %.3g GPa; the reference %.3g J/m² "
                "needs E = %.3g GPa (same ν), i.e. the paper's stiffness was nearer %.2g GPa than "
                "its stated ≈ %.2g GPa, or its Γ was rounded; no correction is applied",
                r.gamma_sim_J_m2, in.youngs_sim_Pa / 1e9, in.reference_gamma_sim_J_m2,
                r.youngs_sim_for_reference_Pa / 1e9, r.youngs_sim_for_reference_Pa / 1e9,
                in.youngs_sim_Pa / 1e9);
  *ctx.log << "reproduce: Coh = " << r.cohesion_number << ", Γ at the simulation stiffness "
           << r.gamma_sim_J_m2 << " J/m2\n";
  *result = CohesionJson<nlohmann::json>(in, r);
  (*result)["explanation"] = why;
  (*result)["values"] = {
      {"coh_coated_EP", ValueJson(r.cohesion_number, NAN, "R* = R, E* = E/(2(1-ν²))")},
      {"gamma_sim_J_m2", ValueJson(r.gamma_sim_J_m2, NAN, why)}};
  return true;
}

}  // namespace demcal::workflow
