#pragma once
// LinearisedBaseStep: the base fit's own Gauss–Newton step, from the sensitivities its
// calibration estimated (the response surface over its candidates), kept inside the unit cube.
// SettleBase (base_fit.h) uses it to check a base that it counts as settled by stagnation: more
// budget did not lower χ², but a coarse search can stop there with a parameter it never resolved
// (a Ceres finite-difference step of 0.25 of the range, across which the cost changed sixfold,
// left μr at its start value on the cross-engine `elongated` case with μr fitted; every
// candidate's refit then lowered χ² from 53 to 18–20 by moving the base parameters alone).
//
// The step solves min ‖r + J Δ‖² over the resolved directions of J: singular values at or below
// the sensitivities' own noise (calibrate::JacobianNoiseFloor) or the rank tolerance are left
// out, as the identifiability report leaves them (a direction the runs do not resolve gives no
// step). Coordinates the step would push out of [0, 1] are fixed on that bound and the rest
// solved again (an active set; at most one pass per coordinate).
//
//   const BaseStep s = LinearisedBaseStep(at, base.base_unit, base.jacobian, base.jacobian_sigma);
//   if (s.ok && s.chi2_now - s.chi2_predicted >
//                   BaseStepThreshold(s.rank, s.max_noise_per_sigma, significance))
//     ...simulate s.unit...;  // base_fit.h
//
// Thread-safety: a pure function.
#include <vector>

#include "diagnose/gap/observation.h"

namespace demcal::diagnose {

struct BaseStep {
  bool ok = false;           // some resolved direction moves the point
  std::vector<double> unit;  // the proposed base point (unit cube)
  double chi2_now = 0;       // Σ r², r = (simulated − measured) / σ at the current point
  double chi2_predicted = 0;  // ‖r + J Δ‖², the σ held fixed
  // What the simulation noise alone makes of the predicted drop: with no drop to find, the
  // drop is ‖P e‖², P the projection on the `rank` directions solved, e the simulated means'
  // errors over σ (each sem/σ ≤ max_noise_per_sigma), so it is at most max_noise_per_sigma² ·
  // χ²_rank in distribution.
  int rank = 0;
  double max_noise_per_sigma = 0;
};

// at: the observations with the current prediction filled in (WithPrediction); jacobian
// [observation][parameter] in observable units per unit-cube step, jacobian_sigma its standard
// errors (same shape; empty: not known).
BaseStep LinearisedBaseStep(const std::vector<Observation>& at, const std::vector<double>& unit,
                            const std::vector<std::vector<double>>& jacobian,
                            const std::vector<std::vector<double>>& jacobian_sigma);

// The point a fraction of the way from `from` to `to` (a damped step).
std::vector<double> PartWay(const std::vector<double>& from, const std::vector<double>& to,
                            double fraction);

}  // namespace demcal::diagnose
