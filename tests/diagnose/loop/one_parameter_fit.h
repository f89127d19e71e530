#pragma once
// The base fit the refit stand-ins step from: one base parameter at `base_unit` in the unit
// cube [0, 1], every observable moving by 1 per unit of it, and the refit frame without a
// discrepancy floor, so that σ is the observations' own.
#include <Eigen/Dense>
#include <vector>

#include "diagnose/loop/refit_work.h"

namespace demcal::diagnose {

inline FitState OneParameterFit(ForwardModel& model, double base_unit, int observables) {
  FitState fit;
  fit.point.base_unit = {base_unit};
  fit.prediction = model.Evaluate({fit.point})[0];
  fit.jacobian = Eigen::MatrixXd::Constant(observables, 1, 1.0);
  fit.lower = {0};
  fit.upper = {1};
  return fit;
}

inline refits::Frame FrameWithoutFloor(const std::vector<Observation>& obs, const FitState& fit) {
  DiagnoseOptions options;
  options.discrepancy_floor = 0;
  return refits::MakeFrame(obs, fit, options);
}

}  // namespace demcal::diagnose
