#pragma once
// The model-discrepancy floor estimated from the data (docs/diagnose/thresholds.md, "The
// model-discrepancy floor"). Every observation's σ_i (measurement, simulation standard error, the
// fixed floor of --discrepancy-floor single-run scatters; observation.h) is widened by an extra
// variance φ²·s_i², s_i the observation's single-run scatter: a model-form discrepancy (another
// engine's contact law, a real powder's everything) that moves every observable by a few packings'
// worth in no pattern a library effect has. φ (in single-run scatters) is the moment estimate of
// Paule & Mandel (1982): the φ ≥ 0 at which the floored χ² of a fit equals its degrees of freedom
// n − p, 0 when the χ² is already at or below them. It is the restricted-likelihood-style estimate
// (it counts the p fitted parameters; the plain maximum likelihood, which sets the floored χ² to
// about n, is biased low by the p dimensions the fit absorbed) and needs no prior on φ.
// With q_i = s_i/σ_i and r_i the standardised residuals: χ²(φ) = Σ r_i² / (1 + φ² q_i²).
//
//   double phi = EstimateFloor(r, q, n - p);
//   double chi2 = FlooredChi2(r, q, phi);
//
// Thread-safety: pure functions.
#include <Eigen/Dense>

namespace demcal::diagnose {

// Beyond this many single-run scatters the floor is reported as this value (the residuals are
// then carried by observations with no scatter, which no floor of this shape covers).
inline constexpr double kMaxFloorScatters = 1000;

double FlooredChi2(const Eigen::VectorXd& r, const Eigen::VectorXd& q, double phi);
// dof >= 1. 0 when FlooredChi2(r, q, 0) <= dof.
double EstimateFloor(const Eigen::VectorXd& r, const Eigen::VectorXd& q, int dof);

}  // namespace demcal::diagnose
