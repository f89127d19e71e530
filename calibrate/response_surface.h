#pragma once
// ResponseSurface: a local model of each standardised residual in the unit-cube parameters,
// fitted to the candidates already evaluated near a centre (the best), giving the sensitivity
// matrix J (d residual_i / d u_k, residuals (simulated − measured) / measurement uncertainty)
// with the standard error of each entry. It reuses the evaluations the optimiser made: no extra
// simulation.
//
// Fit: the K successful samples nearest the centre (unit-cube distance; ties by order), with
// K = min(available, 2·q) and q = 1 + n + n(n+1)/2 coefficients of a quadratic; the model is
// quadratic when K = 2q (twice as many points as coefficients, so the fit has as many degrees
// of freedom as unknowns for its noise estimate), else linear (needs K ≥ n + 1). Centred on the
// centre, so J is the linear coefficients whatever the degree. Weighted least squares per
// residual: w = tricube(d / (1.5·d_max)) / (noise² + noise_floor²), the LOESS kernel
// (Cleveland 1979) times the inverse simulation variance. Standard errors:
// (XᵀWX)⁻¹ · max(1, χ²/dof) (never below what the stated noise implies; larger when the model
// misfits). Points that do not span the parameters (rank-deficient design) fall back to
// linear, then fail with a message.
//
//   ResponseSurface s = FitResponseSurface(samples, best_unit);
//   if (s.ok) use(s.jacobian, s.jacobian_sigma);
//
// Thread-safety: plain values and a pure function.
#include <Eigen/Dense>
#include <string>
#include <vector>

#include "calibrate/optimiser.h"

namespace demcal::calibrate {

struct Sample {
  std::vector<double> unit;  // unit-cube point
  TrialResult trial;
};

struct ResponseSurfaceOptions {
  double noise_floor = 0.01;  // standardised; > 0, keeps the weights finite for noise-free runs
  bool allow_quadratic = true;
  bool IsValid(std::string* error) const;
};

struct ResponseSurface {
  bool ok = false;
  std::string message = "not fitted";
  int points = 0;  // samples used
  bool quadratic = false;
  Eigen::MatrixXd jacobian;        // m×n
  Eigen::MatrixXd jacobian_sigma;  // m×n standard errors
  Eigen::VectorXd value;           // fitted residuals at the centre
};

ResponseSurface FitResponseSurface(const std::vector<Sample>& samples,
                                   const std::vector<double>& centre,
                                   const ResponseSurfaceOptions& options = {});

}  // namespace demcal::calibrate
