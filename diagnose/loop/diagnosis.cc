#include "diagnose/loop/diagnosis.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "core/math/number_text.h"
#include "diagnose/loop/base_fit.h"
#include "diagnose/loop/bound_step.h"
#include "diagnose/loop/candidate_step.h"
#include "diagnose/loop/detection_limits.h"
#include "diagnose/loop/diagnosis_message.h"
#include "diagnose/loop/fit_state.h"
#include "diagnose/ranking/discrepancy_floor.h"
#include "diagnose/ranking/ranking.h"
#include "diagnose/ranking/revaluation.h"
#include "objectives/common/input_limits.h"

namespace demcal::diagnose {

bool DiagnoseOptions::IsValid(std::string* error) const {
  namespace limits = objectives::limits;
  if (!limits::kSignificance.Contains(significance))
    return *error = "significance must be in " + limits::kSignificance.Text() + ", got " +
                    core::NumberText(significance),
           false;
  if (!limits::kDiscrepancyFloor.Contains(discrepancy_floor))
    return *error = "discrepancy floor must be in " + limits::kDiscrepancyFloor.Text() +
                    " single-run scatters, got " + core::NumberText(discrepancy_floor),
           false;
  if (!limits::kDiagnoseRefits.Contains(dem_refits))
    return *error = "refits must be in " + limits::kDiagnoseRefits.Text(), false;
  if (!limits::kDiagnoseMaxEffects.Contains(max_effects))
    return *error = "max effects must be in " + limits::kDiagnoseMaxEffects.Text(), false;
  if (!limits::kDiagnoseExtraRefits.Contains(extra_refits))
    return *error = "extra refits must be in " + limits::kDiagnoseExtraRefits.Text(), false;
  return true;
}

namespace {

using Clock = std::chrono::steady_clock;

FitState StartingFit(const BaseCalibration& base, int observations) {
  FitState fit;
  fit.point.base_unit = base.base_unit;
  fit.prediction = base.prediction;
  const int p = static_cast<int>(base.base_unit.size());
  fit.jacobian = Eigen::MatrixXd::Zero(observations, p);
  for (int i = 0; i < observations && i < static_cast<int>(base.jacobian.size()); ++i)
    for (int j = 0; j < p && j < static_cast<int>(base.jacobian[i].size()); ++j)
      fit.jacobian(i, j) = base.jacobian[i][j];
  fit.lower.assign(p, 0.0);
  fit.upper.assign(p, 1.0);
  return fit;
}

// The discrepancy floor the residuals of a fit with `fitted` parameters carry
// (discrepancy_floor.h).
double EstimatedFloor(const std::vector<Observation>& at, int fitted) {
  const std::vector<double> r = Residuals(at);
  return EstimateFloor(Eigen::Map<const Eigen::VectorXd>(r.data(), r.size()), ScatterPerSigma(at),
                       static_cast<int>(at.size()) - fitted);
}

std::string Names(const std::vector<int>& named, const std::vector<CandidateEffect>& candidates) {
  std::string s;
  for (int c : named) s += (s.empty() ? "" : " + ") + candidates[c].key;
  return s;
}

// `after_fit` is what the "after" figures describe: the fit with the named effects and the
// re-valued parameters (the base model's own mechanisms at the values the data ask for); for
// "not told apart", the worse tied refit. So χ²/dof after says how well the answer fits.
// unit_signatures: the last candidate step's, per entry (the detection limits).
void Finish(const std::vector<Observation>& observations, const FitState& fit,
            const FitState& after_fit, const DiagnoseOptions& options,
            const std::vector<CandidateEffect>& candidates,
            const std::vector<std::vector<double>>& unit_signatures, Diagnosis* d) {
  d->final_point = fit.point;
  if (!d->steps.empty())
    d->detection_limits = DetectionLimitsAtFit(observations, fit, d->steps.back(),
                                               unit_signatures, candidates, options, *d);
  d->fitted_parameters_after = after_fit.Fitted();
  d->after = WithPrediction(observations, after_fit.prediction, options.discrepancy_floor);
  d->gap_after = TestGap(d->after, after_fit.Fitted(), {options.significance});
  d->floor_after = EstimatedFloor(d->after, after_fit.Fitted());
  d->message = DiagnosisMessage(*d, options, candidates);
}

// "wall_friction (more wall friction: delta_mu_w = 0.49; delta BIC -92.4)".
std::string AddedTieText(const RankingEntry& e, const EffectParameter& p) {
  return e.key + " (" + EffectDirection(p, e.values[0]) + ": " + p.name + " = " +
         core::NumberText(e.values[0], 3) + (p.unit.empty() ? "" : " " + p.unit) +
         "; delta BIC " + core::NumberText(e.evidence.delta_bic, 3) + ")";
}

// Adds one step's re-valuation note to the diagnosis' ("; then " after an earlier one).
void AppendRevaluationNote(const std::string& note, Diagnosis* d) {
  d->revaluation_note += (d->revaluation_note.empty() ? "" : "; then ") + note;
}

// The re-valuation rule (revaluation.h): the step's entry whose refit joins the fit as a
// re-valued modelled parameter, with d->revalued and its note filled; −1 when the answer is not
// a re-valuation. Without a tie: the winner, when it re-values a modelled parameter. With one
// (RevaluationOfTie): the winner when both re-value (both listed), or the one that is less than
// assumed when the other adds a mechanism (that one kept in d->revaluation_tie).
int RevaluedEntry(const DiagnosisStep& step, const std::vector<CandidateEffect>& candidates,
                  Diagnosis* d) {
  const int w = step.ranking.winner, t = step.ranking.tied;
  auto parameter = [&](int i) -> const EffectParameter& {
    return candidates[step.entries[i].candidate].parameters[0];
  };
  auto value = [&](int i) {
    return step.entries[i].values.empty() ? NAN : step.entries[i].values[0];
  };
  int revalued = -1, added_tie = -1;
  std::vector<int> listed;
  if (t < 0) {
    if (IsRevaluation(parameter(w), value(w))) revalued = w, listed = {w};
  } else {
    const int which = RevaluationOfTie(parameter(w), value(w), parameter(t), value(t));
    if (which >= 0) {
      revalued = which == 0 ? w : t;
      const int other = which == 0 ? t : w;
      if (IsRevaluation(parameter(other), value(other)))
        listed = {revalued, other};
      else
        listed = {revalued}, added_tie = other;
    }
  }
  if (revalued < 0) return -1;
  std::string note;
  for (int i : listed) {
    const RankingEntry& e = step.entries[i];
    d->revalued.push_back({e.candidate, e.values});
    note += (note.empty() ? "" : "; or ") +
            RevaluationText(e.key, parameter(i), e.values[0], e.chi2_per_dof);
  }
  if (added_tie >= 0) {
    const RankingEntry& e = step.entries[added_tie];
    d->revaluation_tie = {e.candidate, e.values};
    note += "; an added effect fitted within noise of it, " +
            AddedTieText(e, parameter(added_tie)) +
            ", tried again only where a gap remains with the re-valued parameter in the fit";
  }
  AppendRevaluationNote(note, d);
  return revalued;
}

// The control guard's set-aside winner (ranking.h), when it only re-values a modelled
// parameter: true, with d->revalued and its note filled (the control that fitted about as well
// said beside it).
bool SetAsideRevalues(const DiagnosisStep& step, const std::vector<CandidateEffect>& candidates,
                      Diagnosis* d) {
  const int a = step.ranking.set_aside;
  const RankingEntry& e = step.entries[a];
  const EffectParameter& p = candidates[e.candidate].parameters[0];
  if (e.control || e.values.empty() || !IsRevaluation(p, e.values[0])) return false;
  d->revalued.push_back({e.candidate, e.values});
  AppendRevaluationNote(RevaluationText(e.key, p, e.values[0], e.chi2_per_dof) +
                            "; a control fitted about as well (" + step.ranking.message +
                            "), both re-tune the base model",
                        d);
  return true;
}

// Of the tied refits, the one whose gap test gives the larger χ²/dof: "not told apart: X or Y"
// offers either effect, so the fit it promises is the worse one. Fills each one's χ²/dof.
FitState WorseTiedFit(const std::vector<const FitState*>& tied,
                      const std::vector<Observation>& observations,
                      const DiagnoseOptions& options, std::vector<double>* chi2_per_dof) {
  const FitState* worse = tied.front();
  double worst = -1;
  for (const FitState* t : tied) {
    const GapReport g =
        TestGap(WithPrediction(observations, t->prediction, options.discrepancy_floor),
                t->Fitted(), {options.significance});
    chi2_per_dof->push_back(g.chi2_per_dof);
    if (g.chi2_per_dof > worst) worst = g.chi2_per_dof, worse = t;
  }
  return *worse;
}

}  // namespace

Diagnosis Diagnose(ForwardModel& model, const std::vector<Observation>& observations,
                   const std::vector<CandidateEffect>& candidates, const DiagnoseOptions& options,
                   const DiagnoseProgress& progress) {
  Diagnosis d;
  const auto start = Clock::now();
  std::string error;
  if (!options.IsValid(&error)) {
    d.termination = DiagnosisTermination::kInvalid;
    d.message = error;
    return d;
  }
  if (progress) progress("calibrating the base model");
  const BaseFit settled =
      SettleBase(model, observations, options.discrepancy_floor, options.significance, progress,
                 options.screen);
  d.base = settled.base;
  d.base_budget_scale = settled.budget_scale;
  d.base_identifiability = settled.identifiability;
  d.base_summary = settled.summary;
  d.base_at_bound = settled.at_bound;
  d.base_steps = settled.steps;
  if (progress) progress(settled.summary);
  d.phases.push_back({"base calibration", model.SimulationsRun(),
                      std::chrono::duration<double>(Clock::now() - start).count()});
  if (!d.base.ok || !d.base.prediction.ok) {
    d.message = "the base calibration gave no prediction: " + d.base.message;
    return d;
  }
  FitState fit = StartingFit(d.base, static_cast<int>(observations.size()));
  // The fit "after" describes when it is not the fit's own: the worse tied refit for "not told
  // apart".
  FitState answer_fit;
  d.before = WithPrediction(observations, fit.prediction, options.discrepancy_floor);
  d.gap_before = TestGap(d.before, fit.Fitted(), {options.significance});
  d.floor_before = EstimatedFloor(d.before, fit.Fitted());
  if (progress) progress("base model: " + d.gap_before.summary);
  bool gap = d.gap_before.gap_detected;
  d.termination =
      gap ? DiagnosisTermination::kModelFormOffset : DiagnosisTermination::kNoMissingEffect;
  if (gap && !d.base.settled) {  // an unsettled base leaves a gap its own calibration would close
    d.termination = DiagnosisTermination::kBaseUnsettled;
    gap = false;
  }
  // A base within noise on a bound of its range is still compared with the effects that would
  // let it back inside (bound_step.h): one step, whose verdict may replace "no missing effect".
  const bool bound_probe = !gap && !settled.bounds.empty() &&
                           d.termination == DiagnosisTermination::kNoMissingEffect;
  // A settled base within noise and inside its range is screened (diagnosis.h step 2): one step,
  // whose answer changes only on a candidate significant by its own test at α/K.
  d.screened = options.screen && !gap && settled.bounds.empty() && d.base.settled &&
               d.termination == DiagnosisTermination::kNoMissingEffect;
  // Re-valued parameters taken into the fit (revaluation.h): they count against max_effects
  // as the named effects do, so a diagnosis makes at most max_effects steps beyond the base.
  int revalued_steps = 0;
  std::vector<std::vector<double>> last_unit_signatures;
  while ((gap || ((bound_probe || d.screened) && d.steps.empty())) &&
         static_cast<int>(d.named.size()) + revalued_steps < options.max_effects) {
    std::vector<int> remaining;
    for (int c = 0; c < static_cast<int>(candidates.size()); ++c)
      if (!d.Named(c) && !d.MechanismNamed(candidates, c) && !d.Revalued(c))
        remaining.push_back(c);
    if (remaining.empty()) break;
    const auto step_start = Clock::now();
    const bool first = d.steps.empty();
    StepOutcome s = RunCandidateStep(model, observations, candidates, remaining, fit, options,
                                     progress, first ? settled.bounds : std::vector<BaseBound>{});
    s.step.wall_time_s = std::chrono::duration<double>(Clock::now() - step_start).count();
    d.phases.insert(d.phases.end(), s.phases.begin(), s.phases.end());
    d.steps.push_back(s.step);
    last_unit_signatures = s.unit_signatures;
    if (progress) progress("ranking: " + s.step.ranking.message);
    if (first && !settled.bounds.empty()) {
      const BoundCheck b = CheckBound(s, fit, observations, candidates, settled.bounds,
                                      model.BaseParameterNames(), options);
      d.bound = b.judgement;
      d.bound_effect = b.effect_candidate >= 0 ? candidates[b.effect_candidate].key : "";
      d.bound_effect_value = b.effect_value;
      d.bound_effect_base_unit = b.effect_base_unit;
      d.bound_effect_chi2_per_dof = b.effect_chi2_per_dof;
      d.bound_parameters = b.parameters;
      d.bound_note = b.text;
      if (progress) progress("base on a bound: " + b.text);
      if (b.judgement.verdict == BoundVerdict::kNotToldApart) {
        d.termination = DiagnosisTermination::kNotToldApart;
        d.not_told_apart = {b.effect_candidate};
        if (b.also_candidate >= 0) d.not_told_apart.push_back(b.also_candidate);
        d.separating = b.separating;
        break;
      }
      // Without a gap only an effect that rules the bound out goes on to be named.
      if (!gap && b.judgement.verdict != BoundVerdict::kEffect) break;
    }
    // Without a gap (the screen) a step with nothing to name leaves "no missing effect".
    const DiagnosisTermination nothing = d.screened && first
                                             ? DiagnosisTermination::kNoMissingEffect
                                             : DiagnosisTermination::kModelFormOffset;
    // A re-valuation's refit becomes the fit: the base model's own mechanism at the value the
    // data ask for. A gap left beyond it is the next step's question (an effect missing beside
    // the offset); none left: the answer is the offset, or the effects named before.
    auto take_revalued = [&](const FitState& revalued_fit) {
      fit = revalued_fit;
      ++revalued_steps;
      gap = TestGap(WithPrediction(observations, fit.prediction, options.discrepancy_floor),
                    fit.Fitted(), {options.significance})
                .gap_detected;
      d.termination = !d.named.empty() ? (gap ? DiagnosisTermination::kGapRemains
                                              : DiagnosisTermination::kEffectFound)
                                       : DiagnosisTermination::kModelFormOffset;
      if (progress) progress("re-valued: " + d.revaluation_note);
    };
    if (s.step.ranking.control_first) {
      d.control_note = s.step.ranking.message;
      // With a gap, the winner the guard set aside, when it only re-values a modelled
      // parameter, re-tunes the base model as the control does and fits better: it joins the
      // fit (nothing named), and the next step asks what is missing beside the offset.
      if (gap && s.has_set_aside && SetAsideRevalues(s.step, candidates, &d)) {
        take_revalued(s.set_aside_fit);
        continue;
      }
      d.termination = d.named.empty() ? nothing : DiagnosisTermination::kGapRemains;
      break;
    }
    if (const int revalued = s.has_winner ? RevaluedEntry(s.step, candidates, &d) : -1;
        revalued >= 0) {
      take_revalued(revalued == s.step.ranking.winner ? s.next : s.tied_fit);
      continue;
    }
    if (s.has_winner && s.step.ranking.tied >= 0) {
      d.termination =
          d.named.empty() ? DiagnosisTermination::kNotToldApart : DiagnosisTermination::kGapRemains;
      d.not_told_apart = {s.step.entries[s.step.ranking.winner].candidate,
                          s.step.entries[s.step.ranking.tied].candidate};
      d.separating = s.step.separating;
      // After a named effect the tie is the next step's question; "after" stays the named fit.
      if (d.named.empty()) {
        d.after_tied = true;
        answer_fit = WorseTiedFit({&s.next, &s.tied_fit}, observations, options,
                                    &d.tied_chi2_per_dof_after);
      }
      break;
    }
    if (!s.has_winner) {
      d.termination = d.named.empty() ? nothing : DiagnosisTermination::kGapRemains;
      break;
    }
    d.named.push_back(s.step.entries[s.step.ranking.winner].candidate);
    const int alternative = s.step.ranking.same_mechanism;
    d.named_law_alternative.push_back(alternative >= 0 ? s.step.entries[alternative].candidate
                                                       : -1);
    fit = s.next;
    const GapReport g =
        TestGap(WithPrediction(observations, fit.prediction, options.discrepancy_floor),
                fit.Fitted(), {options.significance});
    gap = g.gap_detected;
    d.termination = gap ? DiagnosisTermination::kGapRemains : DiagnosisTermination::kEffectFound;
    if (progress) progress("with " + Names(d.named, candidates) + ": " + g.summary);
  }
  // With nothing named, "after" is the re-valued fit (model form) unless a tie followed it.
  d.after_revalued = !d.revalued.empty() && d.named.empty() && !d.after_tied;
  Finish(observations, fit, d.after_tied ? answer_fit : fit, options, candidates,
         last_unit_signatures, &d);
  d.simulations = model.SimulationsRun();
  d.simulations_reused = model.SimulationsReused();
  d.wall_time_s = std::chrono::duration<double>(Clock::now() - start).count();
  return d;
}

}  // namespace demcal::diagnose
