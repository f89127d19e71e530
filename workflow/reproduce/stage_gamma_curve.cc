// Stage 4, the Γ(w) curve (paper Fig. 6): the per-level Γ of stage 3 with their σ fitted by
// weighted least squares (calibrate/curve_fit.h, Ceres) in the workflow's form (linear, linear
// through the origin, power law), with the coefficients' covariance, the residuals and the 1σ
// band. A level without a finite σ > 0 (its calibration could not estimate one) is left out of
// the fit and listed: without its noise it cannot be weighted.
#include <cmath>

#include "calibrate/curve_fit.h"
#include "workflow/reproduce/stages.h"

namespace demcal::workflow {

bool RunGammaCurveStage(ReproduceContext& ctx, nlohmann::json* result, std::string* /*error*/) {
  const WorkflowCoating& c = ctx.workflow->coating;
  std::vector<calibrate::CurvePoint> points;
  nlohmann::json left_out = nlohmann::json::array();
  bool synthetic = false;
  for (const nlohmann::json& level : ctx.results["gamma_per_coating"]["levels"]) {
    const double w = level["wt_pct"].get<double>();
    const bool ok = level["value"].is_number() && level["sigma"].is_number() &&
                    level["sigma"].get<double>() > 0;
    if (!ok) {
      left_out.push_back({{"wt_pct", w}, {"why", "no value or no sigma > 0 from its calibration"}});
      continue;
    }
    synthetic = synthetic || level["synthetic"].get<bool>();
    points.push_back({w, level["value"].get<double>(), level["sigma"].get<double>()});
  }
  nlohmann::json values = nlohmann::json::object();
  calibrate::CurveFitResult fit;
  std::string why;
  if (!calibrate::FitCurve(c.curve_form, points, &fit, &why)) {
    *ctx.log << "reproduce: Γ(w) not fitted: " << why << "\n";
    *result = {{"fitted", false}, {"why", why}, {"left_out", left_out}, {"values", values}};
    return true;
  }
  nlohmann::json residuals = nlohmann::json::array();
  for (size_t i = 0; i < points.size(); ++i)
    residuals.push_back({{"wt_pct", points[i].x}, {"gamma_J_m2", points[i].y},
                         {"sigma_J_m2", points[i].sigma}, {"residual_J_m2", fit.residuals[i]}});
  nlohmann::json band = nlohmann::json::array();
  double hi = 0;
  for (const auto& p : points) hi = std::max(hi, p.x);
  for (int i = 0; i <= 40; ++i) {
    const double w = (c.curve_form == calibrate::CurveForm::kPowerLaw ? 0.05 : 0) + i * hi * 1.05 / 40;
    band.push_back({{"wt_pct", w}, {"gamma_J_m2", fit.Evaluate(w)},
                    {"sigma_J_m2", std::isfinite(fit.StandardError(w)) ? fit.StandardError(w) : 0}});
  }
  const double coated = ctx.workflow->segregation.coated_wt_pct;
  *result = {{"fitted", true},
             {"form", calibrate::CurveFormKey(c.curve_form)},
             {"coefficients", fit.coefficients},
             {"covariance", fit.covariance},
             {"covariance_note", fit.covariance_note},
             {"chi2", fit.chi2},
             {"dof", fit.dof},
             {"chi2_per_dof", std::isfinite(fit.chi2_per_dof) ? nlohmann::json(fit.chi2_per_dof)
                                                              : nlohmann::json()},
             {"points", residuals},
             {"left_out", left_out},
             {"band", band},
             {"synthetic", synthetic},
             {"coated_wt_pct", coated},
             {"gamma_at_coated_J_m2", fit.Evaluate(coated)},
             {"gamma_at_coated_sigma_J_m2", fit.StandardError(coated)},
             {"values", values}};
  *ctx.log << "reproduce: Γ(w) " << calibrate::CurveFormKey(c.curve_form) << ": Γ("
           << coated << " wt%) = " << fit.Evaluate(coated) << " J/m2\n";
  return true;
}

}  // namespace demcal::workflow
