#include "calibrate/curve_fit.h"

#include <ceres/ceres.h>

#include <cmath>
#include <limits>

namespace demcal::calibrate {
namespace {

// f(x; c) of a form, templated for Ceres' automatic derivatives.
template <typename T>
T CurveValue(CurveForm form, const T* c, double x) {
  switch (form) {
    case CurveForm::kLinear: return c[0] + c[1] * x;
    case CurveForm::kLinearThroughOrigin: return c[0] * x;
    case CurveForm::kPowerLaw: return c[0] * pow(T(x), c[1]);
  }
  return T(0);
}

// N: the form's coefficient count (its parameter block size). The coefficients are copied into
// a block of two so that no instantiation reads past its block (CurveValue indexes c[1] for the
// two-coefficient forms; the one-coefficient form never reaches that branch).
template <int N>
struct PointResidual {
  CurveForm form;
  CurvePoint p;
  template <typename T>
  bool operator()(const T* c, T* residual) const {
    const T both[2] = {c[0], N > 1 ? c[N > 1 ? 1 : 0] : T(0)};
    residual[0] = (CurveValue(form, both, p.x) - T(p.y)) / T(p.sigma);
    return true;
  }
};

// Starting coefficients: a straight line through the first and last point (in log–log space for
// the power law), so Levenberg–Marquardt starts in the right basin.
std::vector<double> Start(CurveForm form, const std::vector<CurvePoint>& pts) {
  const CurvePoint& a = pts.front();
  const CurvePoint& b = pts.back();
  switch (form) {
    case CurveForm::kLinear: {
      double slope = b.x != a.x ? (b.y - a.y) / (b.x - a.x) : 0;
      return {a.y - slope * a.x, slope};
    }
    case CurveForm::kLinearThroughOrigin: return {b.x != 0 ? b.y / b.x : 1};
    case CurveForm::kPowerLaw: {
      if (a.y > 0 && b.y > 0 && a.x != b.x) {
        double k = std::log(b.y / a.y) / std::log(b.x / a.x);
        return {a.y / std::pow(a.x, k), k};
      }
      return {b.y / b.x, 1};
    }
  }
  return {};
}

bool Validate(CurveForm form, const std::vector<CurvePoint>& pts, std::string* error) {
  const int n = CurveCoefficientCount(form);
  if (static_cast<int>(pts.size()) < n) {
    *error = std::string("curve fit '") + CurveFormKey(form) + "': " + std::to_string(pts.size()) +
             " points for " + std::to_string(n) + " coefficients";
    return false;
  }
  for (size_t i = 0; i < pts.size(); ++i) {
    const CurvePoint& p = pts[i];
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.sigma) || p.sigma <= 0) {
      *error = "curve fit: point " + std::to_string(i + 1) + " needs finite x, y and sigma > 0";
      return false;
    }
    if (form == CurveForm::kPowerLaw && p.x <= 0) {
      *error = "curve fit 'power_law': point " + std::to_string(i + 1) + " has x <= 0";
      return false;
    }
  }
  return true;
}

}  // namespace

double CurveFitResult::Evaluate(double x) const {
  if (coefficients.empty()) return std::numeric_limits<double>::quiet_NaN();
  return CurveValue(form, coefficients.data(), x);
}

double CurveFitResult::StandardError(double x) const {
  if (covariance.empty()) return std::numeric_limits<double>::quiet_NaN();
  std::vector<double> g;  // ∂f/∂c at x
  switch (form) {
    case CurveForm::kLinear: g = {1, x}; break;
    case CurveForm::kLinearThroughOrigin: g = {x}; break;
    case CurveForm::kPowerLaw: {
      double v = std::pow(x, coefficients[1]);
      g = {v, coefficients[0] * v * std::log(x)};
      break;
    }
  }
  double var = 0;
  for (size_t i = 0; i < g.size(); ++i)
    for (size_t j = 0; j < g.size(); ++j) var += g[i] * covariance[i][j] * g[j];
  return std::sqrt(std::max(var, 0.0));
}

bool FitCurve(CurveForm form, const std::vector<CurvePoint>& points, CurveFitResult* out,
              std::string* error) {
  if (!Validate(form, points, error)) return false;
  CurveFitResult r;
  r.form = form;
  r.coefficients = Start(form, points);
  const int n = CurveCoefficientCount(form);
  ceres::Problem problem;
  for (const CurvePoint& p : points) {
    ceres::CostFunction* cost = nullptr;
    if (n == 1) {
      cost = new ceres::AutoDiffCostFunction<PointResidual<1>, 1, 1>(new PointResidual<1>{form, p});
    } else {
      cost = new ceres::AutoDiffCostFunction<PointResidual<2>, 1, 2>(new PointResidual<2>{form, p});
    }
    problem.AddResidualBlock(cost, nullptr, r.coefficients.data());
  }
  ceres::Solver::Options options;
  options.max_num_iterations = 200;
  options.function_tolerance = 1e-14;
  options.parameter_tolerance = 1e-14;
  options.gradient_tolerance = 1e-16;
  options.logging_type = ceres::SILENT;
  ceres::Solver::Summary summary;
  ceres::Solve(options, &problem, &summary);
  if (!summary.IsSolutionUsable()) {
    *error = "curve fit: Ceres found no usable solution: " + summary.message;
    return false;
  }
  ceres::Covariance::Options co;
  co.algorithm_type = ceres::DENSE_SVD;
  ceres::Covariance covariance(co);
  std::vector<std::pair<const double*, const double*>> blocks = {
      {r.coefficients.data(), r.coefficients.data()}};
  if (covariance.Compute(blocks, &problem)) {
    std::vector<double> c(n * n);
    covariance.GetCovarianceBlock(r.coefficients.data(), r.coefficients.data(), c.data());
    r.covariance.assign(n, std::vector<double>(n));
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) r.covariance[i][j] = c[i * n + j];
  } else {
    r.covariance_note = "ceres::Covariance failed (rank-deficient: the points do not fix every "
                        "coefficient)";
  }
  for (const CurvePoint& p : points) {
    double res = p.y - r.Evaluate(p.x);
    r.residuals.push_back(res);
    r.chi2 += (res / p.sigma) * (res / p.sigma);
  }
  r.dof = static_cast<int>(points.size()) - n;
  r.chi2_per_dof = r.dof > 0 ? r.chi2 / r.dof : std::numeric_limits<double>::quiet_NaN();
  *out = std::move(r);
  return true;
}

}  // namespace demcal::calibrate
