#pragma once
// FitCurve: weighted least squares of a ParameterCurve form (linear, linear through the origin,
// power law; parameter_curve.h) to points (x, y ± σ) with Ceres, and the covariance of the
// coefficients (ceres::Covariance, DENSE_SVD) — the paper's Fig. 6, Γ against the coating level,
// fitted to the per-level calibrated Γ with their σ. The covariance is the plain weighted one,
// (JᵀWJ)⁻¹ with W = 1/σ², not rescaled by χ²/dof (chi2_per_dof says how well the σ explain the
// scatter: ≫ 1 means the form or the σ are wrong).
//
//   CurveFitResult fit;  std::string error;
//   if (!FitCurve(CurveForm::kLinear, {{0.5, 0.041, 0.004}, ...}, &fit, &error)) ...;
//   double band = fit.StandardError(2.5);  // 1σ of the fitted curve at w = 2.5
#include <string>
#include <vector>

#include "calibrate/parameter_curve.h"

namespace demcal::calibrate {

struct CurvePoint {
  double x = 0, y = 0, sigma = 0;  // sigma > 0
};

struct CurveFitResult {
  CurveForm form = CurveForm::kLinear;
  std::vector<double> coefficients;             // c0 (, c1)
  std::vector<std::vector<double>> covariance;  // of the coefficients; empty if not computed
  std::vector<double> residuals;                // (y − f(x)) per point, in y's unit
  double chi2 = 0;                              // Σ ((y − f(x))/σ)²
  int dof = 0;                                  // points − coefficients
  double chi2_per_dof = 0;                      // NaN when dof = 0
  std::string covariance_note;                  // why the covariance is missing, if it is
  double Evaluate(double x) const;
  // 1σ of f(x) from the covariance (delta method); NaN without a covariance.
  double StandardError(double x) const;
};

// False (with the reason) for fewer points than coefficients, a σ ≤ 0 or non-finite input, or a
// power law with x ≤ 0.
bool FitCurve(CurveForm form, const std::vector<CurvePoint>& points, CurveFitResult* out,
              std::string* error);

}  // namespace demcal::calibrate
