#include "diagnose/ranking/detection_limit.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "calibrate/chi_square.h"
#include "diagnose/ranking/f_distribution.h"

namespace demcal::diagnose {
namespace {

// √F at the upper `level` tail of F(1, dof): the t statistic's two-sided critical value.
double FCritical(double level, double dof) {
  double lo = 0, hi = 1;
  while (FSurvival(hi * hi, 1, dof) > level && hi < 1e6) hi *= 2;
  for (int k = 0; k < 200; ++k) {
    const double mid = 0.5 * (lo + hi);
    (FSurvival(mid * mid, 1, dof) > level ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

// The standard normal quantile at p in (0, 1).
double NormalQuantile(double p) {
  if (p == 0.5) return 0;
  return p > 0.5 ? calibrate::NormalTwoSidedQuantile(2 * (1 - p))
                 : -calibrate::NormalTwoSidedQuantile(2 * p);
}

}  // namespace

DetectionLimit SmallestDetectable(const Eigen::MatrixXd& J, const Eigen::VectorXd& s,
                                  const Eigen::VectorXd& q, double phi, double per_candidate,
                                  double power) {
  const Eigen::Index n = s.size(), p = J.cols();
  Eigen::VectorXd weight(n);
  for (Eigen::Index i = 0; i < n; ++i) weight(i) = 1 / std::sqrt(1 + phi * phi * q(i) * q(i));
  const Eigen::VectorXd sw = weight.cwiseProduct(s);
  Eigen::VectorXd off = sw;
  if (p > 0) {
    const Eigen::MatrixXd Jw = weight.asDiagonal() * J;
    off -= Jw * Jw.completeOrthogonalDecomposition().solve(sw);
  }
  DetectionLimit d;
  d.projected_norm = off.norm();
  const double dof = static_cast<double>(n - p - 1);
  d.critical = dof >= 1 ? FCritical(per_candidate, dof)
                        : calibrate::NormalTwoSidedQuantile(per_candidate);
  d.critical = std::max(d.critical, std::sqrt(std::log(static_cast<double>(std::max<Eigen::Index>(n, 2)))));
  // The statistic with an estimated scale is a non-central t: its spread about √λ is
  // √(1 + c²/(2ν)) rather than 1 (the normal approximation to the non-central t).
  const double spread = dof >= 1 ? std::sqrt(1 + d.critical * d.critical / (2 * dof)) : 1.0;
  const double z = NormalQuantile(power) * spread;
  // Below 1e-6 of the signature the fitted parameters mimic it: no size of it is seen.
  if (d.projected_norm <= 1e-6 * sw.norm() || d.projected_norm == 0) {
    d.magnitude = d.magnitude_half = std::numeric_limits<double>::infinity();
    return d;
  }
  d.magnitude = (d.critical + z) / d.projected_norm;
  d.magnitude_half = d.critical / d.projected_norm;
  return d;
}

}  // namespace demcal::diagnose
