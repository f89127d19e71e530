#include "calibrate/jacobian_svd.h"

namespace demcal::calibrate {

JacobianSvd DecomposeJacobian(const Eigen::MatrixXd& jacobian, double noise_floor) {
  const Eigen::Index n = jacobian.cols();
  JacobianSvd out;
  out.values = Eigen::VectorXd::Zero(n);
  out.vectors = Eigen::MatrixXd::Identity(n, n);
  if (n == 0) return out;
  if (jacobian.rows() > 0) {
    Eigen::JacobiSVD<Eigen::MatrixXd> svd(jacobian, Eigen::ComputeFullV);
    out.values.head(svd.singularValues().size()) = svd.singularValues();
    out.vectors = svd.matrixV();
  }
  const double s_max = out.values(0);
  for (Eigen::Index i = 0; i < n; ++i)
    if (out.values(i) > 0 && out.values(i) > kRankTolerance * s_max && out.values(i) > noise_floor)
      out.rank = static_cast<int>(i) + 1;
  // Sign convention: the largest component of each vector is positive (reports are stable).
  for (Eigen::Index i = 0; i < n; ++i) {
    Eigen::Index k = 0;
    out.vectors.col(i).cwiseAbs().maxCoeff(&k);
    if (out.vectors(k, i) < 0) out.vectors.col(i) *= -1;
  }
  return out;
}

double JacobianNoiseFloor(const Eigen::MatrixXd& jacobian_sigma) {
  if (jacobian_sigma.size() == 0 || !jacobian_sigma.allFinite()) return 0;
  return jacobian_sigma.norm();  // Frobenius
}

}  // namespace demcal::calibrate
