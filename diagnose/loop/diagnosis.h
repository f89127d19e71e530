#pragma once
// Diagnose: the discrepancy workflow (docs/diagnose.md; docs/design.md "The discrepancy workflow").
//  1. Calibrate the base model until it settles by the calibration's own criterion (base_fit.h:
//     at most kMaxBaseBudgetScale × the study's budget; unsettled: nothing is ranked); the
//     identifiability of its parameters; standardised residuals per observation
//     (observation.h) and the gap test (gap_significance.h).
//  2. No gap: "no missing effect found" — after one screening step (steps 3-4 once, when
//     options.screen and the base settled inside its range): the omnibus χ² spreads its power
//     over n − p directions, a candidate's own test is one directed degree of freedom. Only a
//     candidate significant by its own test at α/K can change the answer (the same rules as
//     with a gap: named, not told apart, or a re-valuation, "model-form offset"); a control
//     first, or nothing significant, leaves "no missing effect" (docs/diagnose/ranking.md,
//     "The screen without a gap").
//  3. Else, per candidate effect not yet added: its signature — one simulated point, the
//     current fit with the effect at its probe value (same seeds) — and a linearised
//     (Gauss–Newton) refit of base + effect from the sensitivities alone (linear_refit.h).
//  4. The `dem_refits` best linearised candidates whose linear evidence is significant are
//     refitted for real: the Gauss–Newton point is simulated, the signature corrected by the
//     secant through it, a second Gauss–Newton point simulated, then re-centred points (the
//     sensitivities re-estimated at the candidate's best point, one damped Gauss–Newton step
//     from there) while each lowers that candidate's best χ² by at least 1 (at most extra_refits):
//     candidates are compared at their converged refits. A simulated refit that is not
//     significant passes its slot to the next linearised candidate (until dem_refits are
//     significant, the linear shortlist is used up, or 2·dem_refits were simulated). Ranking by evidence (ranking.h): ΔBIC
//     and likelihood ratio of the simulated refits, with the signature match beside them.
//     The evidence carries the discrepancy floor estimated from the data (evidence.h) at α/K.
//  5. The winner is added (its refitted point becomes the current fit, its signature a fitted
//     direction), the gap tested again, and 3-5 repeated while a significant gap remains (at
//     most max_effects). No winner: "model-form offset". Two within ΔBIC 6: "not told apart"
//     with the measurement that would separate them (separating_measurement.h). A control
//     (a copy of a fitted parameter) first or level with the winner: "model-form offset / no
//     missing effect", never the control. A winner (and its tie, if any) that only re-values
//     a parameter the base model already has, by no more than its assumed value
//     (revaluation.h): "model-form offset" with the re-valuation stated, not named. Two laws
//     of one mechanism within ΔBIC 6 (JKR and sjkr adhesion) name the mechanism with the
//     better-fitting law and say the law is not told apart; once a mechanism is named, its
//     other laws are not tried on top of it.
// A base fitted onto a bound of its range (gap or not) gets the first step with the controls
// copying that parameter refitted and the best effects refitted again with it held inside
// (candidate_step.h); bound_step.h judges: an effect that rules the bound out goes on, one
// as good as the bound gives "not told apart: the parameter beyond its range or the effect".
// Frugal by construction: one base calibration, one simulated point per candidate and
// iteration, two plus at most extra_refits × (base parameters + 3) per refitted candidate.
//
//   Diagnosis d = Diagnose(model, observations, candidates, options);
//   d.termination;  // kNoMissingEffect, kEffectFound, kNotToldApart, kModelFormOffset, ...
//
// Thread-safety: runs on the calling thread; the model parallelises.
#include <algorithm>
#include <functional>
#include <string>
#include <vector>

#include "calibrate/identifiability.h"
#include "diagnose/gap/gap_significance.h"
#include "diagnose/loop/base_fit.h"
#include "diagnose/loop/diagnosis_termination.h"
#include "diagnose/loop/forward_model.h"
#include "diagnose/ranking/bound_alternative.h"
#include "diagnose/ranking/detection_limit.h"
#include "diagnose/ranking/observables_carried.h"
#include "diagnose/ranking/ranking.h"
#include "diagnose/ranking/separating_measurement.h"

namespace demcal::diagnose {

// Allowed ranges: objectives/common/input_limits.h (kSignificance, kDiscrepancyFloor, ...).
struct DiagnoseOptions {
  double significance = 0.01;  // the gap test's and the evidence's level
  double discrepancy_floor =
      1;                 // the fixed part of the floor, in single-run scatters (one packing)
  int dem_refits = 2;    // candidates refitted by simulation per iteration
  int max_effects = 2;   // effects added at most
  int extra_refits = 4;  // re-centred refit points per refitted candidate beyond two
  bool screen = true;    // no gap on a settled base inside its range: one candidate step anyway
  bool IsValid(std::string* error) const;
};

struct DiagnosisStep {
  std::vector<RankingEntry> entries;  // one per candidate tried
  std::vector<std::vector<double>>
      signatures;  // [entry][observation]: simulated change at the probe
  std::vector<std::vector<double>>
      refit_residuals;  // [entry][observation]: standardised, at its refit
  Ranking ranking;
  std::vector<ObservableShare> carried;  // when there is a winner
  SeparatingMeasurement separating;      // when the winner is not told apart (ranking.tied)
  int simulations = 0;
  double wall_time_s = 0;
};

struct PhaseTime {
  std::string phase;  // "base calibration", "signatures", "refits"
  int simulations = 0;
  double wall_time_s = 0;
};

// What the data could not have seen (detection_limits.h): one candidate effect still open at
// the end, the smallest size of it its own test would have found at kDetectionPower.
struct EffectDetection {
  int candidate = -1;
  DetectionLimit limit;
  double lower = 0, upper = 0;  // its parameter's range: a limit beyond it is not detectable there
  bool has_signature = true;    // false: its signature run had no value (no limit)
};

struct Diagnosis {
  DiagnosisTermination termination = DiagnosisTermination::kFailed;
  std::string message = "Diagnose was not called";
  BaseCalibration base;
  int base_budget_scale = 1;  // the study's budget times this (base_fit.h)
  calibrate::IdentifiabilityReport base_identifiability;
  std::string base_summary;         // settled or not, budget, undetermined base parameters
  std::vector<std::string> base_at_bound;  // base parameters fitted onto a bound (base_fit.h)
  std::vector<BaseStepRecord> base_steps;  // linearised steps after stagnation (base_fit.h)
  // A base fitted onto a bound, against the effects that let it back inside (bound_step.h):
  // the judgement (entry indices of the first step; kNotJudged when nothing is on a bound), the
  // effect judged, "mu_s_BP_BP beyond its lower bound", and the verdict's sentence.
  BoundJudgement bound;
  std::string bound_effect, bound_parameters, bound_note;
  double bound_effect_value = 0;
  std::vector<double> bound_effect_base_unit;  // the base parameters of that effect's refit
  double bound_effect_chi2_per_dof = 0;
  std::vector<Observation> before;  // at the base calibration
  GapReport gap_before;
  // The gap test found no gap and one screening step was run (step 2): every answer other than
  // "no missing effect" then rests on a candidate's own test, and the message says so.
  bool screened = false;
  // The discrepancy floor estimated from the residuals (discrepancy_floor.h), in single-run
  // scatters beyond the fixed one: at the base fit and at the final fit.
  double floor_before = 0, floor_after = 0;
  std::vector<DiagnosisStep> steps;
  std::vector<int> named;            // candidate indices added, in order
  // Per named effect: another law of its mechanism that the data did not tell apart from it
  // (candidate index; −1: none). The mechanism is named, with the better-fitting law's values.
  std::vector<int> named_law_alternative;
  std::vector<int> not_told_apart;   // candidate indices of the last step's tie (kNotToldApart)
  SeparatingMeasurement separating;  // the measurement that would tell them apart
  std::string control_note;          // why the control guard held (a model-form offset)
  // The best-ranked effects that only re-value a modelled parameter (revaluation.h), with
  // their refitted values: a model-form offset, not named; empty when none. The winner's refit
  // joins the fit (final_point), and the loop goes on while a gap remains beside it.
  std::vector<ActiveEffect> revalued;
  std::string revaluation_note;
  // An added effect that fitted within noise of a re-valuation that is less of a modelled
  // mechanism than assumed (RevaluationOfTie): not named, tried again on the re-valued
  // fit when a gap remains there. candidate −1: none.
  ActiveEffect revaluation_tie{-1, {}};
  ModelPoint final_point;  // the base with the re-valued parameters and the named effects
  // True when the answer re-values modelled parameters and names nothing: `after`, `gap_after`
  // and `floor_after` then describe the re-valued fit (final_point).
  bool after_revalued = false;
  // True when the answer is "not told apart" between two effects with nothing named: `after`,
  // `gap_after` and `floor_after` then describe the tied refit that fits worse, since the answer
  // offers either effect and closes the gap only as far as the worse of them
  // (docs/diagnose/ranking.md). tied_chi2_per_dof_after: χ²/dof of the gap test at each tied
  // refit, in the order of not_told_apart.
  bool after_tied = false;
  std::vector<double> tied_chi2_per_dof_after;
  // Per candidate effect still open at the end (not named, re-valued or a control), the
  // smallest size the data would have shown at kDetectionPower; empty when no candidate step ran.
  std::vector<EffectDetection> detection_limits;
  std::vector<Observation> after;  // at the final point, the re-valued fit or the worse tie
  GapReport gap_after;
  int fitted_parameters_after = 0;
  std::vector<PhaseTime> phases;
  int simulations = 0, simulations_reused = 0;
  double wall_time_s = 0;

  // Whether candidate c was named, or re-values a modelled parameter (in `revalued`).
  // Another law of a named effect's mechanism (SameMechanism) is named with it.
  bool MechanismNamed(const std::vector<CandidateEffect>& candidates, int c) const {
    return std::any_of(named.begin(), named.end(), [&](int n) {
      return SameMechanism(candidates[n].mechanism, candidates[c].mechanism);
    });
  }
  bool Named(int c) const { return std::find(named.begin(), named.end(), c) != named.end(); }
  bool Revalued(int c) const {
    return std::any_of(revalued.begin(), revalued.end(),
                       [c](const ActiveEffect& a) { return a.candidate == c; });
  }
};

using DiagnoseProgress = std::function<void(const std::string& line)>;

Diagnosis Diagnose(ForwardModel& model, const std::vector<Observation>& observations,
                   const std::vector<CandidateEffect>& candidates, const DiagnoseOptions& options,
                   const DiagnoseProgress& progress = {});

}  // namespace demcal::diagnose
