#include "diagnose/ranking/discrepancy_floor.h"

#include <algorithm>
#include <cmath>

namespace demcal::diagnose {

double FlooredChi2(const Eigen::VectorXd& r, const Eigen::VectorXd& q, double phi) {
  double chi2 = 0;
  for (Eigen::Index i = 0; i < r.size(); ++i) chi2 += r(i) * r(i) / (1 + phi * phi * q(i) * q(i));
  return chi2;
}

double EstimateFloor(const Eigen::VectorXd& r, const Eigen::VectorXd& q, int dof) {
  const double target = std::max(1, dof);
  if (FlooredChi2(r, q, 0) <= target) return 0;
  if (FlooredChi2(r, q, kMaxFloorScatters) > target) return kMaxFloorScatters;
  // χ²(φ) falls monotonically in φ: bisection on log φ between 1e-6 and the cap.
  double lo = std::log(1e-6), hi = std::log(kMaxFloorScatters);
  if (FlooredChi2(r, q, std::exp(lo)) <= target) return std::exp(lo);
  for (int k = 0; k < 100; ++k) {
    const double mid = 0.5 * (lo + hi);
    (FlooredChi2(r, q, std::exp(mid)) > target ? lo : hi) = mid;
  }
  return std::exp(0.5 * (lo + hi));
}

}  // namespace demcal::diagnose
