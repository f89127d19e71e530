#pragma once
// FindSeparatingMeasurement: when two effects explain the gap about equally (ranking.h: not
// told apart), the measurement that would tell them apart. Calibrate's "which measurement would
// help" (calibrate/target_gain.h) on the model with both effects: the standardised
// sensitivities [J | S_a | S_b] (the fitted parameters and the two effects' parameters), each
// observation of the study as a candidate target measured once more at its uncertainty; the
// one that shrinks the σ of the two effects' parameters most (the product of their shrink
// factors; a target that lifts the a–b valley first) is named, with what each effect's refit
// predicts there. Where the two refits' predictions differ by less than one σ at every
// observation, no observation of this study separates them and the description says a new
// observable or condition is needed (one σ: a difference a single measurement at the stated
// uncertainty can see).
//
//   SeparatingMeasurement m = FindSeparatingMeasurement(Js, Sa, Sb, ra, rb, observations);
//   m.description;  // "angle_deg at coating_PEG_wt_pct=3 (aor_bp_heap.json): ..."
//
// Thread-safety: pure function.
#include <Eigen/Dense>
#include <string>
#include <vector>

#include "diagnose/gap/observation.h"

namespace demcal::diagnose {

struct SeparatingMeasurement {
  int observation = -1;     // index into the observations (-1: none)
  double prediction_a = 0;  // the effects' refits' simulated values there
  double prediction_b = 0;
  double difference_sigma = 0;        // |a − b| / σ there
  double shrink_a = 1, shrink_b = 1;  // σ after / σ before of each effect's parameter
  bool lifts_valley = false;
  bool separates = false;  // the largest difference over the observations is ≥ 1 σ
  std::string description;
};

// Js: standardised sensitivities to the fitted parameters (n × p); sa, sb: the two effects'
// standardised signatures per unit parameter; ra, rb: the standardised residuals at their
// refits; sigma: each observation's σ; names: the two effects' keys.
SeparatingMeasurement FindSeparatingMeasurement(
    const Eigen::MatrixXd& Js, const Eigen::VectorXd& sa, const Eigen::VectorXd& sb,
    const Eigen::VectorXd& ra, const Eigen::VectorXd& rb, const Eigen::VectorXd& sigma,
    const std::vector<Observation>& observations, const std::string& name_a,
    const std::string& name_b);

}  // namespace demcal::diagnose
