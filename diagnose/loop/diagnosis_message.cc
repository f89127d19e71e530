#include "diagnose/loop/diagnosis_message.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/math/number_text.h"
#include "diagnose/loop/base_fit.h"
#include "diagnose/ranking/ranking.h"
#include "diagnose/ranking/revaluation.h"

namespace demcal::diagnose {

namespace {

// "jkr_adhesion or particle_shape (delta BIC -12.1 and -11.4, within 6)" from the last step.
std::string TieText(const Diagnosis& d, const std::vector<CandidateEffect>& candidates) {
  std::ostringstream s;
  s.precision(3);
  const DiagnosisStep& step = d.steps.back();
  const RankingEntry& a = step.entries[step.ranking.winner];
  const RankingEntry& b = step.entries[step.ranking.tied];
  auto one = [&candidates](const RankingEntry& e) {
    const EffectParameter& p = candidates[e.candidate].parameters[0];
    return e.key + " (" + (e.values.empty() ? "" : EffectDirection(p, e.values[0])) + ")";
  };
  s << one(a) << " or " << one(b) << " explain the " << (d.screened ? "misfit" : "gap")
    << " about equally (delta BIC " << a.evidence.delta_bic << " and " << b.evidence.delta_bic
    << "; BIC gap " << std::fabs(BicGap(a.evidence, b.evidence))
    << " under the common floor, within " << IndistinctWithin(a.evidence, b.evidence) << ")";
  return s.str();
}

// "rolling_resistance (less rolling resistance than assumed, delta_mu_r = -0.06)" per named
// effect; an effect whose law was not told apart from another of its mechanism is preceded by
// "adhesion, law not told apart: sjkr_cohesion or jkr_adhesion; the better fit: ".
std::string Signed(const Diagnosis& d, const ModelPoint& point,
                   const std::vector<CandidateEffect>& candidates) {
  std::ostringstream s;
  s.precision(3);
  for (const ActiveEffect& a : point.effects) {
    if (!d.Named(a.candidate))
      continue;  // a re-valued modelled parameter: model form, said apart (RevaluedText)
    const CandidateEffect& c = candidates[a.candidate];
    const EffectParameter& p = c.parameters[0];
    s << (s.tellp() > 0 ? " + " : "");
    for (size_t k = 0; k < d.named.size() && k < d.named_law_alternative.size(); ++k)
      if (d.named[k] == a.candidate && d.named_law_alternative[k] >= 0)
        s << c.mechanism << ", law not told apart: " << c.key << " or "
          << candidates[d.named_law_alternative[k]].key << "; the better fit: ";
    s << c.key << " (" << EffectDirection(p, a.values[0]) << ", " << p.name << " = "
      << a.values[0] << (p.unit.empty() ? "" : " " + p.unit) << ")";
  }
  return s.str();
}

// The screen's sentence (diagnosis.h step 2): the directed test of the step's winner, or of its
// best simulated candidate when none won, beside the omnibus gap test that did not flag.
std::string ScreenText(const Diagnosis& d, const DiagnoseOptions& options) {
  const DiagnosisStep& step = d.steps.front();
  const double per_candidate =
      options.significance / static_cast<double>(std::max<size_t>(1, step.entries.size()));
  const int best = DecidingEntry(step.ranking, step.entries);
  std::ostringstream s;
  s.precision(3);
  if (best < 0) return "screened without a gap: no candidate";
  const RankingEntry& e = step.entries[best];
  s << (step.ranking.winner >= 0 ? "found by its own directed test" : "screened without a gap")
    << " (" << (step.ranking.winner >= 0 ? "" : "best candidate ") << e.key
    << (e.simulated ? "" : ", linearised refit: none was significant enough to simulate")
    << ": likelihood-ratio p " << e.evidence.lr_p_value
    << (e.evidence.significant ? " below" : ", not below") << " significance/K = " << per_candidate
    << ") while the omnibus gap test did not flag (chi-square p " << d.gap_before.p_value << ")";
  if (step.ranking.control_first)
    s << "; a control (a copy of a fitted parameter) ranks first or level with the best effect, "
         "so none is named";
  return s.str();
}

// Beside "gap not explained by the library": the step's best simulated candidate when the data
// favour it over the base by Schwarz's criterion (ΔBIC < 0) though not at significance/K, with
// the row its refit moves most toward the data. Not an answer — no effect is named — but a DEM
// engineer reading "not explained" should learn which mechanism came closest and what to
// measure again to decide (a gap carried by one row whose simulated response is noisy: the
// cross-engine `wide_psd`, results_screen.md).
std::string BestNotNamedText(const Diagnosis& d, const DiagnoseOptions& options,
                             const std::vector<CandidateEffect>& candidates) {
  if (d.steps.empty()) return "";
  const DiagnosisStep& step = d.steps.back();
  const int best = DecidingEntry(step.ranking, step.entries);
  if (best < 0 || !step.entries[best].simulated || step.entries[best].control ||
      !(step.entries[best].evidence.delta_bic < 0) || step.entries[best].values.empty())
    return "";
  if (d.Revalued(step.entries[best].candidate)) return "";  // said as the re-valuation
  const RankingEntry& e = step.entries[best];
  const std::vector<double>& r = step.refit_residuals[best];
  int row = -1;
  double gain = 0;
  for (size_t i = 0; i < d.before.size() && i < r.size(); ++i) {
    const double g = std::fabs(d.before[i].Residual()) - std::fabs(r[i]);
    if (g > gain) gain = g, row = static_cast<int>(i);
  }
  const EffectParameter& p = candidates[e.candidate].parameters[0];
  std::ostringstream s;
  s.precision(3);
  s << "; the best candidate, not named: " << e.key << " (" << EffectDirection(p, e.values[0])
    << ", " << p.name << " = " << e.values[0] << "; delta BIC " << e.evidence.delta_bic
    << ", likelihood-ratio p " << e.evidence.lr_p_value << ", not below significance/K = "
    << options.significance / static_cast<double>(std::max<size_t>(1, step.entries.size()))
    << ")";
  if (row >= 0)
    s << "; its refit moves " << d.before[row].name << " from " << d.before[row].Residual()
      << " to " << r[row] << " sigma: more repeats there (or of the runs) would decide";
  return s.str();
}

// The gap after either tied effect; the answer's "after" is the worse (diagnosis.h).
std::string TiedAfterText(const Diagnosis& d, const std::vector<CandidateEffect>& candidates) {
  if (!d.after_tied) return "";
  std::string s = "; with either effect the gap is chi2/dof ";
  for (size_t k = 0; k < d.tied_chi2_per_dof_after.size() && k < d.not_told_apart.size(); ++k)
    s += (k ? " and " : "") + core::NumberText(d.tied_chi2_per_dof_after[k], 3) + " (" +
         candidates[d.not_told_apart[k]].key + ")";
  return s + "; after the worse: " + d.gap_after.summary;
}

// Beside an answer that names effects or a tie: the re-valued modelled parameters in the fit.
std::string RevaluedText(const Diagnosis& d) {
  if (d.revaluation_note.empty()) return "";
  return "; with a re-valued modelled parameter in the fit (model form, not named): " +
         d.revaluation_note;
}

// "; smaller effects can hide in these data: at 90 % power they would have shown wall_friction
// (delta_mu_w >= 0.35 or <= -0.35), size_polydispersity (none within its range, -1 to 1.5)"
// (detection_limits.h); "" when no candidate is open.
std::string DetectionText(const Diagnosis& d, const std::vector<CandidateEffect>& candidates) {
  if (d.detection_limits.empty()) return "";
  std::ostringstream s;
  s.precision(3);
  s << "; smaller effects can hide in these data: at " << 100 * kDetectionPower
    << " % power (linearised at the final fit) they would have shown ";
  for (size_t k = 0; k < d.detection_limits.size(); ++k) {
    const EffectDetection& e = d.detection_limits[k];
    const EffectParameter& p = candidates[e.candidate].parameters[0];
    s << (k ? ", " : "") << candidates[e.candidate].key << " (";
    const double m = e.limit.magnitude;
    const bool up = e.upper > 0 && m <= e.upper, down = e.lower < 0 && m <= -e.lower;
    if (!e.has_signature)
      s << "no limit: its signature run had no value";
    else if (!up && !down)
      s << "none within its range, " << e.lower << " to " << e.upper;
    else
      s << (up ? p.name + " >= " : "") << (up ? core::NumberText(m, 3) : "")
        << (up && down ? " or " : "") << (down ? p.name + " <= " : "")
        << (down ? core::NumberText(-m, 3) : "");
    s << ")";
  }
  return s.str();
}

}  // namespace

std::string DiagnosisMessage(const Diagnosis& d, const DiagnoseOptions& options,
                             const std::vector<CandidateEffect>& candidates) {
  std::ostringstream m;
  if (!d.base_identifiability.Identifiable() && !d.base_identifiability.singular_values.empty()) {
    m << "the data do not determine the base parameters (";
    for (const calibrate::UndeterminedDirection& u : d.base_identifiability.undetermined)
      m << u.description;
    m << "); ";
  }
  if (d.termination == DiagnosisTermination::kBaseUnsettled) {
    m << "no effect ranked: " << d.base_summary
      << "; raise the study's max_evaluations (or --max-evaluations) until it settles ("
      << d.gap_before.summary << ")";
  } else if (d.termination == DiagnosisTermination::kNoMissingEffect) {
    m << "no missing effect found: the base model fits within noise (" << d.gap_before.summary
      << ")";
    if (d.screened && !d.steps.empty()) m << "; " << ScreenText(d, options);
    if (options.screen && !d.screened && !d.base.settled && d.base_at_bound.empty())
      m << "; not screened (the candidates' own tests need a settled base): the base calibration "
           "did not settle within "
        << kMaxBaseBudgetScale << "x the study's budget; raise max_evaluations to screen";
    m << DetectionText(d, candidates);
    if (!d.bound_note.empty()) {
      m << "; but the base fit ends on a bound: " << d.bound_note;
    } else if (!d.base_at_bound.empty()) {
      m << "; but the base fit ends on a bound (";
      for (size_t k = 0; k < d.base_at_bound.size(); ++k)
        m << (k ? ", " : "") << d.base_at_bound[k];
      m << "): the data may ask for a value beyond the study's range, and an effect that moves "
           "the observables as that parameter does would be absorbed there; widen the range to "
           "see where the fit goes";
    }
  } else if (d.termination == DiagnosisTermination::kEffectFound) {
    m << "missing effect: " << Signed(d, d.final_point, candidates) << RevaluedText(d)
      << "; after adding it " << d.gap_after.summary;
  } else if (d.termination == DiagnosisTermination::kNotToldApart &&
             d.bound.verdict == BoundVerdict::kNotToldApart) {
    m << "not told apart: " << d.bound_note << "; " << d.separating.description;
  } else if (d.termination == DiagnosisTermination::kNotToldApart) {
    m << "not told apart: " << TieText(d, candidates) << "; " << d.separating.description
      << RevaluedText(d) << TiedAfterText(d, candidates);
  } else if (d.termination == DiagnosisTermination::kGapRemains) {
    m << "added " << Signed(d, d.final_point, candidates) << " but a gap remains ("
      << d.gap_after.summary << "), not explained by the library";
    if (!d.not_told_apart.empty())
      m << "; next, not told apart: " << TieText(d, candidates) << "; "
        << d.separating.description;
    if (!d.control_note.empty()) m << "; " << d.control_note;
    m << RevaluedText(d);
  } else if (!d.revaluation_note.empty()) {
    m << "model-form offset: the data re-value a parameter the base model already has ("
      << d.revaluation_note
      << "), by no more than its assumed value; an offset in that mechanism's law (another "
         "engine's, a real powder's) fits the same, so no missing effect is named; calibrate "
         "that parameter in the base to measure it (base: "
      << d.gap_before.summary << "; re-valued: " << d.gap_after.summary << ")";
    if (d.gap_after.gap_detected)
      m << "; a gap remains beside the re-valued parameter, not explained by the library"
        << BestNotNamedText(d, options, candidates);
    m << DetectionText(d, candidates);
  } else if (!d.control_note.empty()) {
    m << "model-form offset / no missing effect: " << d.control_note << " (discrepancy floor "
      << core::NumberText(d.floor_before, 3) << " single-run scatter(s) beyond the fixed "
      << options.discrepancy_floor << "; " << d.gap_before.summary << ")"
      << DetectionText(d, candidates);
  } else {
    m << "model-form offset: the base model misses the data by a discrepancy floor of "
      << core::NumberText(d.floor_before, 3) << " single-run scatter(s) beyond the fixed "
      << options.discrepancy_floor
      << ", and no effect of the library explains more than that floor "
      << "allows (gap not explained by the library: " << d.gap_before.summary << ")"
      << BestNotNamedText(d, options, candidates) << DetectionText(d, candidates);
  }
  if (d.screened && !d.steps.empty() && d.termination != DiagnosisTermination::kNoMissingEffect)
    m << "; " << ScreenText(d, options);
  if (!d.bound_note.empty() && d.termination != DiagnosisTermination::kNoMissingEffect &&
      d.bound.verdict != BoundVerdict::kNotToldApart)
    m << "; the base fit ended on a bound: " << d.bound_note;
  return m.str();
}

}  // namespace demcal::diagnose
