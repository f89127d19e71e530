#include "diagnose/ranking/linear_refit.h"

#include <algorithm>
#include <cmath>

namespace demcal::diagnose {
namespace {

Eigen::VectorXd Solve(const Eigen::MatrixXd& A, const Eigen::VectorXd& b) {
  if (A.cols() == 0) return Eigen::VectorXd();
  return A.completeOrthogonalDecomposition().solve(b);
}

void ClampDelta(const std::vector<double>& lower, const std::vector<double>& upper, Eigen::VectorXd* delta) {
  for (Eigen::Index j = 0; j < delta->size() && j < static_cast<Eigen::Index>(lower.size()); ++j)
    (*delta)(j) = std::clamp((*delta)(j), lower[j], upper[j]);
}

}  // namespace

LinearRefitResult LinearRefit(const Eigen::VectorXd& r0, const Eigen::MatrixXd& J, const Eigen::MatrixXd& S,
                              const std::vector<double>& t_lower, const std::vector<double>& t_upper,
                              const std::vector<double>& delta_lower, const std::vector<double>& delta_upper) {
  const Eigen::Index p = J.cols(), k = S.cols();
  Eigen::MatrixXd A(r0.size(), p + k);
  A << J, S;
  Eigen::VectorXd x = Solve(A, -r0);
  LinearRefitResult out;
  out.delta = x.head(p);
  out.t = x.tail(k);
  bool clamped = false;
  for (Eigen::Index j = 0; j < k; ++j) {
    const double c = std::clamp(out.t(j), t_lower[j], t_upper[j]);
    clamped = clamped || c != out.t(j);
    out.t(j) = c;
  }
  if (clamped) out.delta = Solve(J, -(r0 + S * out.t));
  if (out.delta.size() == 0) out.delta = Eigen::VectorXd::Zero(p);
  ClampDelta(delta_lower, delta_upper, &out.delta);
  out.residuals = r0 + J * out.delta + S * out.t;
  out.chi2 = out.residuals.squaredNorm();
  return out;
}

double SignatureMatch(const Eigen::VectorXd& r0, const Eigen::MatrixXd& J, const Eigen::VectorXd& signature) {
  auto project = [&J](const Eigen::VectorXd& v) -> Eigen::VectorXd {
    if (J.cols() == 0) return v;
    return v - J * Solve(J, v);
  };
  const Eigen::VectorXd a = project(-r0), b = project(signature);
  if (b.norm() <= 1e-6 * signature.norm() || a.norm() == 0) return 0;
  return a.dot(b) / (a.norm() * b.norm());
}

}  // namespace demcal::diagnose
