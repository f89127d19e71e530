#pragma once
// CheckBound: the loop's side of a base fitted onto a bound (base_fit.h; the rule is
// bound_alternative.h). After the first candidate step, run with the bound parameters so that
// the controls copying them and the effects that move them inward were refitted by simulation
// (candidate_step.h), it gathers what JudgeBound needs — which simulated refits put every bound
// parameter back inside its range, which entries copy a bound parameter, the base's own
// evidence — judges, names the measurement that would separate the two explanations when they
// are not told apart (separating_measurement.h: the bound parameter's own sensitivity stands
// for "beyond its range"), and says it in words.
//
//   BoundCheck b = CheckBound(step, fit, observations, candidates, bounds, names, options);
//   if (b.judgement.verdict == BoundVerdict::kNotToldApart) ...
//
// Thread-safety: pure function.
#include <string>
#include <vector>

#include "diagnose/loop/base_fit.h"
#include "diagnose/loop/candidate_step.h"
#include "diagnose/ranking/bound_alternative.h"

namespace demcal::diagnose {

struct BoundCheck {
  BoundJudgement judgement;   // entry indices: the step's entries, then its inside_entries
  int effect_candidate = -1;  // the candidate of judgement.effect (−1: none)
  double effect_value = 0;    // its refitted parameter
  std::vector<double> effect_base_unit;  // and base parameters (unit cube)
  double effect_chi2_per_dof = 0;
  // kNotToldApart: the step's own significant winner when it fits better than the effect of the
  // tie without outranking both beyond their noise: a third explanation level with them (−1: none).
  int also_candidate = -1;
  SeparatingMeasurement separating;  // kNotToldApart: between the effect and the bound
  std::string parameters;            // "mu_s_BP_BP beyond its lower bound"
  std::string text;                  // the verdict's sentence
};

BoundCheck CheckBound(const StepOutcome& step, const FitState& fit,
                      const std::vector<Observation>& observations,
                      const std::vector<CandidateEffect>& candidates,
                      const std::vector<BaseBound>& bounds, const std::vector<std::string>& names,
                      const DiagnoseOptions& options);

}  // namespace demcal::diagnose
