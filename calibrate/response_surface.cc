#include "calibrate/response_surface.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "calibrate/chi_square.h"

namespace demcal::calibrate {
namespace {

// A row keeps its quadratic fit only when the curvature terms lower its weighted χ² by more than
// the χ² quantile at this probability for as many degrees of freedom as they add (the usual 5 %
// test of nested least-squares models): otherwise the extra coefficients fit noise and inflate
// the standard errors of the slopes (seen on the DEM rig twin: a floor of 12 against a second
// singular value of 6.85 after refinement).
constexpr double kCurvatureSignificance = 0.95;

// Design row: 1, d_k, then d_a·d_b (a ≤ b) when quadratic.
Eigen::VectorXd Row(const std::vector<double>& d, bool quadratic) {
  const size_t n = d.size();
  const size_t q = quadratic ? 1 + n + n * (n + 1) / 2 : 1 + n;
  Eigen::VectorXd x(q);
  x(0) = 1;
  for (size_t k = 0; k < n; ++k) x(1 + k) = d[k];
  if (quadratic) {
    size_t c = 1 + n;
    for (size_t a = 0; a < n; ++a)
      for (size_t b = a; b < n; ++b) x(c++) = d[a] * d[b];
  }
  return x;
}

// Weighted least squares per residual row; chi2 (if given) receives each row's weighted χ².
bool Fit(const std::vector<const Sample*>& near, const std::vector<double>& centre,
         const std::vector<double>& kernel, bool quadratic, double floor, ResponseSurface* s,
         Eigen::VectorXd* chi2_rows = nullptr) {
  const size_t n = centre.size(), m = near[0]->trial.residuals.size();
  const Eigen::Index q = quadratic ? 1 + n + n * (n + 1) / 2 : 1 + n;
  const Eigen::Index k_points = static_cast<Eigen::Index>(near.size());
  Eigen::MatrixXd x(k_points, q);
  for (Eigen::Index p = 0; p < k_points; ++p) {
    std::vector<double> d(n);
    for (size_t k = 0; k < n; ++k) d[k] = near[p]->unit[k] - centre[k];
    x.row(p) = Row(d, quadratic).transpose();
  }
  s->jacobian.resize(m, n);
  s->jacobian_sigma.resize(m, n);
  s->value.resize(m);
  if (chi2_rows) chi2_rows->resize(static_cast<Eigen::Index>(m));
  for (size_t i = 0; i < m; ++i) {
    Eigen::VectorXd w(k_points), y(k_points);
    for (Eigen::Index p = 0; p < k_points; ++p) {
      const TrialResult& t = near[p]->trial;
      const double noise = i < t.noise.size() ? t.noise[i] : 0.0;
      w(p) = kernel[p] / (noise * noise + floor * floor);
      y(p) = t.residuals[i];
    }
    const Eigen::MatrixXd xtw = x.transpose() * w.asDiagonal();
    const Eigen::MatrixXd normal = xtw * x;
    Eigen::FullPivLU<Eigen::MatrixXd> lu(normal);
    if (lu.rank() < q) return false;
    const Eigen::VectorXd beta = lu.solve(xtw * y);
    const Eigen::VectorXd misfit = y - x * beta;
    const double chi2 = misfit.dot(w.asDiagonal() * misfit);
    if (chi2_rows) (*chi2_rows)(static_cast<Eigen::Index>(i)) = chi2;
    const Eigen::Index dof = k_points - q;
    const double scale = dof > 0 ? std::max(1.0, chi2 / static_cast<double>(dof)) : 1.0;
    const Eigen::MatrixXd cov = lu.inverse() * scale;
    s->value(i) = beta(0);
    for (size_t k = 0; k < n; ++k) {
      s->jacobian(i, k) = beta(1 + k);
      s->jacobian_sigma(i, k) = std::sqrt(std::max(cov(1 + k, 1 + k), 0.0));
    }
  }
  s->quadratic = quadratic;
  s->points = static_cast<int>(k_points);
  s->ok = true;
  return true;
}

}  // namespace

bool ResponseSurfaceOptions::IsValid(std::string* error) const {
  if (!(noise_floor > 0 && noise_floor <= 1)) {
    if (error) *error = "noise_floor: must be in (0, 1]";
    return false;
  }
  return true;
}

ResponseSurface FitResponseSurface(const std::vector<Sample>& samples,
                                   const std::vector<double>& centre,
                                   const ResponseSurfaceOptions& options) {
  ResponseSurface s;
  const size_t n = centre.size();
  std::vector<const Sample*> ok;
  size_t m = 0;
  for (const Sample& smp : samples) {
    if (!smp.trial.ok || smp.unit.size() != n || smp.trial.residuals.empty()) continue;
    if (ok.empty()) m = smp.trial.residuals.size();
    if (smp.trial.residuals.size() == m) ok.push_back(&smp);
  }
  auto dist = [&](const Sample* a) {
    double d2 = 0;
    for (size_t k = 0; k < n; ++k) d2 += (a->unit[k] - centre[k]) * (a->unit[k] - centre[k]);
    return std::sqrt(d2);
  };
  std::stable_sort(ok.begin(), ok.end(),
                   [&](const Sample* a, const Sample* b) { return dist(a) < dist(b); });
  const size_t q2 = 2 * (1 + n + n * (n + 1) / 2);
  ok.resize(std::min(ok.size(), q2));
  if (ok.size() < n + 1) {
    s.message = "fewer than n + 1 = " + std::to_string(n + 1) + " successful candidates to fit";
    return s;
  }
  const double d_max = 1.5 * std::max(dist(ok.back()), 1e-12);
  std::vector<double> kernel;
  for (const Sample* p : ok) {
    const double r = dist(p) / d_max;
    kernel.push_back(std::pow(1 - r * r * r, 3));
  }
  const bool quadratic = options.allow_quadratic && ok.size() == q2;
  ResponseSurface linear;
  Eigen::VectorXd chi2_quadratic, chi2_linear;
  if (quadratic && Fit(ok, centre, kernel, true, options.noise_floor, &s, &chi2_quadratic) &&
      Fit(ok, centre, kernel, false, options.noise_floor, &linear, &chi2_linear)) {
    const double limit = ChiSquareQuantile(kCurvatureSignificance, static_cast<double>(n * (n + 1) / 2));
    int linear_rows = 0;
    for (Eigen::Index i = 0; i < s.jacobian.rows(); ++i) {
      if (chi2_linear(i) - chi2_quadratic(i) > limit) continue;
      s.jacobian.row(i) = linear.jacobian.row(i);
      s.jacobian_sigma.row(i) = linear.jacobian_sigma.row(i);
      s.value(i) = linear.value(i);
      ++linear_rows;
    }
    s.message =
        "quadratic fit through the " + std::to_string(s.points) + " candidates nearest the best";
    if (linear_rows > 0)
      s.message += " (" + std::to_string(linear_rows) + " of " + std::to_string(s.jacobian.rows()) +
                   " residuals linear: their curvature was not significant at 5 %)";
    s.quadratic = linear_rows < s.jacobian.rows();
    return s;
  }
  if (Fit(ok, centre, kernel, false, options.noise_floor, &s)) {
    s.message =
        "linear fit through the " + std::to_string(s.points) + " candidates nearest the best";
    return s;
  }
  s.ok = false;
  s.message = "the candidates near the best do not vary every parameter independently";
  return s;
}

}  // namespace demcal::calibrate
