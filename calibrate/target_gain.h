#pragma once
// "Which measurement would help": for candidate extra targets (other observables or
// experiments a study could add), how much each parameter's σ would shrink if that target were
// measured too. A candidate is one row j of sensitivities d observable / d unit-parameter,
// standardised by that target's assumed uncertainty (and its simulation noise, as the rows of
// J are); adding it turns JᵀJ into JᵀJ + j jᵀ, whose pseudo-inverse (parameter_covariance.h)
// gives the new σ. A target that lifts a valley takes σ from +∞ (or from beyond the bounds'
// own σ) to a finite, identifiable value, and removes an undetermined direction
// (identifiability.h).
//
//   std::vector<TargetGain> g = RankCandidateTargets(J, {{"discharge_time_s", {0.4, 3.1}}}, scale);
//   if (g[0].lifts_valley) std::cerr << g[0].description;
//
// Thread-safety: plain values and a pure function.
#include <Eigen/Dense>
#include <string>
#include <vector>

namespace demcal::calibrate {

struct CandidateTarget {
  std::string name;                 // e.g. "discharge_time_s (funnel D = 10 mm)"
  std::vector<double> sensitivity;  // one per parameter: d observable / d u / uncertainty
};

struct TargetGain {
  std::string name;
  std::vector<double> sigma_before;  // SI, +∞ when not determined
  std::vector<double> sigma_after;
  // σ_after / σ_before per parameter (1: no help; 0: from +∞ to finite).
  std::vector<double> shrink;
  std::vector<bool> identifiable_after;
  int undetermined_before = 0;  // undetermined directions (identifiability.h)
  int undetermined_after = 0;
  bool lifts_valley = false;  // fewer undetermined directions with this target
  std::string description;    // in words
};

// J: the current standardised sensitivity matrix (targets × parameters, unit cube); names and
// si_per_unit: one per parameter. Gains in the order of `candidates`.
std::vector<TargetGain> RankCandidateTargets(const Eigen::MatrixXd& jacobian,
                                             const std::vector<CandidateTarget>& candidates,
                                             const std::vector<std::string>& names,
                                             const std::vector<double>& si_per_unit);

}  // namespace demcal::calibrate
