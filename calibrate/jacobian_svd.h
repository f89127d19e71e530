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
// Noise floor: J of a DEM calibration is estimated from noisy runs (a response surface or
// finite differences), each entry with a standard error. A singular value no larger than the
// noise's own size could be made by the noise alone: by Weyl's inequality the noise E moves every
// singular value by at most ||E||₂ ≤ ||E||_F, and E||E||_F² = Σ σ_ij² for independent errors of
// standard deviations σ_ij. So, given the entries' standard errors, a singular value ≤
// JacobianNoiseFloor(σ) = sqrt(Σ σ_ij²) counts as zero: its direction is not resolved above the
// noise, and a covariance built on it would be a fake (found on the DEM twin: a sliding-friction
// column of 17 ± 34 and −68 ± 53 gave σ(μs) = 0.03 at μs = 1.0 for a truth of 0.5).
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

// noise_floor: singular values at or below it count as zero (0: only the rounding tolerance).
JacobianSvd DecomposeJacobian(const Eigen::MatrixXd& jacobian, double noise_floor = 0);

// sqrt(Σ σ_ij²) of the standard errors of J's entries (0 for an empty matrix): see above.
double JacobianNoiseFloor(const Eigen::MatrixXd& jacobian_sigma);

}  // namespace demcal::calibrate
