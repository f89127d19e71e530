#pragma once
// JacobianSvd: the singular value decomposition of a standardised sensitivity matrix J (rows:
// residuals (simulated − measured) / uncertainty, weighted by the simulation noise; columns:
// unit-cube parameters), padded to one singular value per parameter: with fewer targets than
// parameters the missing values are 0 and their right singular vectors span the directions the
// targets cannot see. The shared ground of the covariance, identifiability and "which
// measurement would help" (parameter_covariance.h, identifiability.h, target_gain.h).
//
//   JacobianSvd svd = DecomposeJacobian(J);
//   for (int i = 0; i < svd.values.size(); ++i) if (svd.Null(i)) ...svd.vectors.col(i)...;
//
// Numerical rank: a singular value ≤ kRankTolerance · s_max (or exactly 0) is zero. Finite
// differences of doubles at steps ≥ 0.01 carry a relative rounding error near 1e-14, so
// 1e-10 is safely above rounding and far below any sensitivity a measurement could resolve
// (those are judged by identifiability.h's threshold, not by this one).
//
// Thread-safety: a plain value.
#include <Eigen/Dense>

namespace demcal::calibrate {

inline constexpr double kRankTolerance = 1e-10;

struct JacobianSvd {
  Eigen::VectorXd values;   // n singular values, descending (zero-padded when rows < n)
  Eigen::MatrixXd vectors;  // n×n, column i is the right singular vector of values(i)
  int rank = 0;             // singular values above the tolerance
  bool Null(int i) const { return i >= rank; }
};

JacobianSvd DecomposeJacobian(const Eigen::MatrixXd& jacobian);

}  // namespace demcal::calibrate
