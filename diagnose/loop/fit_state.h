#pragma once
// FitState: the loop's current fit — the model point, its prediction, and the sensitivities of
// every fitted coordinate (the base parameters in the unit cube, then the parameters of the
// effects added so far in their own units), in observable units per unit step. Standardised
// views divide each row by the observation's sigma (observation.h), held fixed within a step so
// that the chi² of different candidates are comparable.
//
// Thread-safety: a plain value.
#include <Eigen/Dense>
#include <vector>

#include "diagnose/gap/observation.h"
#include "diagnose/loop/forward_model.h"

namespace demcal::diagnose {

struct FitState {
  ModelPoint point;
  Prediction prediction;
  Eigen::MatrixXd jacobian;          // observations × fitted coordinates, raw units
  std::vector<double> lower, upper;  // bounds of each fitted coordinate
  int Fitted() const { return static_cast<int>(jacobian.cols()); }
  // The current values of the fitted coordinates.
  std::vector<double> Coordinates() const;
  // point moved by delta (one entry per fitted coordinate) with `added` switched on.
  ModelPoint Step(const Eigen::VectorXd& delta, const ActiveEffect* added) const;
};

// The observations with this prediction's simulated values beside them; floor = factor ×
// single-run scatter / √repeats (the measured value's repeats; none stated: one).
std::vector<Observation> WithPrediction(const std::vector<Observation>& observations,
                                        const Prediction& p, double floor_factor);
Eigen::VectorXd Sigmas(const std::vector<Observation>& observations);
// Per observation its single-run scatter over its sigma (the estimated floor's unit per σ).
Eigen::VectorXd ScatterPerSigma(const std::vector<Observation>& observations);
// (mean − measured) / sigma with fixed sigmas.
Eigen::VectorXd StandardisedResiduals(const std::vector<Observation>& observations,
                                      const std::vector<double>& mean,
                                      const Eigen::VectorXd& sigma);

}  // namespace demcal::diagnose
