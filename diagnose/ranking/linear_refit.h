#pragma once
// LinearRefit: the Gauss–Newton refit of an augmented model from its sensitivities alone (no
// simulation): with r0 the standardised residuals at the current fit, J the standardised
// sensitivities to the fitted parameters (per unit-cube step) and S to the effect's parameters
// (per unit of each), minimise ||r0 + J·δ + S·t||² over δ and t, with t inside the effect's
// bounds and δ inside [delta_lower, delta_upper] (the base kept in its unit cube). Minimum-norm least squares (complete orthogonal
// decomposition), so an effect redundant with the fitted parameters (the sliding-friction
// control when μs is fitted) is solved without blowing up and simply gains nothing. A bound on
// t is enforced by fixing t there and re-solving δ — exact for one effect parameter (a convex
// one-dimensional profile), the library's case.
//
//   LinearRefitResult f = LinearRefit(r0, J, S, {0}, {1}, {-0.5}, {0.5});
//   f.chi2;  // predicted Σ r² after the refit
//
// Thread-safety: pure function.
#include <Eigen/Dense>
#include <vector>

namespace demcal::diagnose {

struct LinearRefitResult {
  Eigen::VectorXd delta;      // step of the fitted parameters (unit cube)
  Eigen::VectorXd t;          // the effect's parameter values
  Eigen::VectorXd residuals;  // predicted standardised residuals
  double chi2 = 0;
};

LinearRefitResult LinearRefit(const Eigen::VectorXd& r0, const Eigen::MatrixXd& J, const Eigen::MatrixXd& S,
                              const std::vector<double>& t_lower, const std::vector<double>& t_upper,
                              const std::vector<double>& delta_lower, const std::vector<double>& delta_upper);

// cos of the angle between −r0 and S·1 once both are projected off the span of J (the part of
// the misfit the fitted parameters cannot absorb against the part of the signature they cannot
// mimic): 1 = the effect moves the observables exactly as the gap asks. 0 when the projected
// signature is below 1e-6 of the signature (redundant with the fitted parameters).
double SignatureMatch(const Eigen::VectorXd& r0, const Eigen::MatrixXd& J, const Eigen::VectorXd& signature);

}  // namespace demcal::diagnose
