// Stage 5, dissimilar pairs (paper section 2.5.3, Eq. 4): Γ of each coated–uncoated pair from the
// coated pair's Γ at the coated scenario's level (the curve of stage 4, else that level's own
// calibration), halved (one adhesive surface) and carried to the pair's reduced radius at
// constant Cohesion number (calibrate/dissimilar_pairs.h, where the radius convention and the
// paper's Eq. 4 typesetting are discussed). σ is carried linearly (Γ_pair ∝ Γ).
#include <cmath>

#include "calibrate/dissimilar_pairs.h"
#include "files/json_document.h"
#include "workflow/reproduce/stages.h"

namespace demcal::workflow {

bool RunDissimilarPairsStage(ReproduceContext& ctx, nlohmann::json* result, std::string* error) {
  (void)error;
  const WorkflowCoating& c = ctx.workflow->coating;
  const nlohmann::json& curve = ctx.results["gamma_curve"];
  double gamma = NAN, sigma = NAN;
  std::string from;
  bool synthetic = false;
  if (curve.value("fitted", false)) {
    gamma = curve["gamma_at_coated_J_m2"].get<double>();
    sigma = curve["gamma_at_coated_sigma_J_m2"].is_number()
                ? curve["gamma_at_coated_sigma_J_m2"].get<double>() : NAN;
    synthetic = curve["synthetic"].get<bool>();
    from = "the fitted Γ(w) curve";
  } else {
    for (const nlohmann::json& level : ctx.results["gamma_per_coating"]["levels"])
      if (level["wt_pct"].get<double>() == ctx.workflow->segregation.coated_wt_pct &&
          level["value"].is_number()) {
        gamma = level["value"].get<double>();
        sigma = level["sigma"].is_number() ? level["sigma"].get<double>() : NAN;
        synthetic = level["synthetic"].get<bool>();
        from = "the level's own calibration (no curve)";
      }
  }
  nlohmann::json pairs = nlohmann::json::array(), values = nlohmann::json::object();
  for (size_t k = 0; k < c.partners.size(); ++k) {
    const double r_pair = calibrate::ReducedRadius(c.coated_radius_m, c.partner_radii_m[k]);
    const double factor = calibrate::DissimilarPairGamma(1.0, c.coated_radius_m, r_pair);
    pairs.push_back({{"materials", {c.material, c.partners[k]}},
                     {"partner_radius_m", c.partner_radii_m[k]},
                     {"pair_reduced_radius_m", r_pair},
                     {"factor", factor},
                     {"gamma_J_m2", std::isfinite(gamma) ? nlohmann::json(gamma * factor) : nlohmann::json()},
                     {"sigma_J_m2", std::isfinite(sigma) ? nlohmann::json(sigma * factor) : nlohmann::json()}});
    values["gamma_" + c.material + "_" + c.partners[k] + "_J_m2"] =
        ValueJson(gamma * factor, sigma * factor,
                  std::isfinite(gamma) ? "Γ/2 (R*_pair/R_coated)^(8/5) from " + from
                                       : "no coated Γ to start from",
                  synthetic);
  }
  *result = {{"coated_gamma_J_m2", NumOrNull(gamma)},
             {"coated_gamma_sigma_J_m2", NumOrNull(sigma)},
             {"from", from},
             {"radius_convention", "R*_coated = the coated granule's radius; R*_pair = R1 R2/(R1+R2) "
                                   "of the equivalent-volume radii"},
             {"synthetic", synthetic},
             {"pairs", pairs},
             {"values", values}};
  return true;
}

}  // namespace demcal::workflow
