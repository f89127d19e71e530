#pragma once
// ParameterCovariance: the uncertainty of calibrated parameters from the standardised
// sensitivity matrix J at the optimum (jacobian_svd.h): the unit-cube covariance
// (JᵀJ)⁻¹ = Σ_i v_i v_iᵀ / s_i² over the non-zero singular values, converted to SI with the
// parameter space's scale dθ/du at the optimum (θ_hi − θ_lo for a linear parameter,
// θ·ln(θ_hi/θ_lo) for a log-scale one), reported as σ per parameter and a correlation matrix.
//
// A rank-deficient J gives no fake finite σ: a parameter with a component (|v_k| > 1e-6) along a
// null singular vector has σ = +∞, is not identifiable, and its correlations are NaN (undefined;
// said so in reports, never used as numbers). A finite σ larger than the bounds' own
// uniform σ = range/sqrt(12) also leaves the parameter not identifiable: the data tell less
// about it than the bounds do.
//
//   ParameterCovariance c = CovarianceFromJacobian(J, SiPerUnit(space, best_unit));
//   if (c.identifiable[0]) report(c.sigma[0]);
//
// Thread-safety: plain values and pure functions.
#include <Eigen/Dense>
#include <string>
#include <vector>

#include "calibrate/parameter_space.h"

namespace demcal::calibrate {

struct ParameterCovariance {
  std::vector<double> sigma_unit;  // σ in the unit cube, +∞ if not determined at all
  std::vector<double> sigma;       // σ in SI (the parameter's unit), +∞ if not determined
  std::vector<bool> identifiable;  // finite σ no larger than the bounds' uniform σ
  Eigen::MatrixXd covariance;      // SI, n×n; rows/columns of +∞-σ parameters are NaN
  Eigen::MatrixXd correlation;     // n×n, NaN where undefined
  int rank = 0;                    // of J
  std::string note;                // how it was obtained
};

// dθ/du of each parameter at a unit-cube point (SI per unit).
std::vector<double> SiPerUnit(const ParameterSpace& space, const std::vector<double>& unit);

// From J (residuals × parameters, standardised, unit cube) by the SVD pseudo-inverse.
// noise_floor: singular values at or below it are not resolved (jacobian_svd.h).
ParameterCovariance CovarianceFromJacobian(const Eigen::MatrixXd& jacobian,
                                           const std::vector<double>& si_per_unit,
                                           double noise_floor = 0);
// From a unit-cube covariance computed elsewhere (ceres::Covariance): full rank by assumption.
ParameterCovariance CovarianceFromUnit(const Eigen::MatrixXd& covariance_unit,
                                       const std::vector<double>& si_per_unit);

}  // namespace demcal::calibrate
