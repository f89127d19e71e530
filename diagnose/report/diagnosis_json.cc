#include "diagnose/report/diagnosis_json.h"

#include <algorithm>
#include <cmath>

#include "core/version.h"

namespace demcal::diagnose {
namespace {

using Json = nlohmann::ordered_json;

Json Number(double x) { return std::isfinite(x) ? Json(x) : Json(nullptr); }

Json ConditionJson(const calibrate::Condition& c) {
  Json j = Json::object();
  for (const auto& [column, cell] : c) j[column] = cell;
  return j;
}

Json ResidualTable(const std::vector<Observation>& obs) {
  Json rows = Json::array();
  for (const Observation& o : obs)
    rows.push_back({{"name", o.name},
                    {"observable", o.observable},
                    {"condition", ConditionJson(o.condition)},
                    {"measured", Number(o.measured)},
                    {"uncertainty", Number(o.uncertainty)},
                    {"simulated", Number(o.simulated)},
                    {"sem", Number(o.sem)},
                    {"floor", Number(o.floor)},
                    {"sigma", Number(o.Sigma())},
                    {"standardised_residual", Number(o.Residual())},
                    // rows with one source share its simulation error (Chi2NoiseSd)
                    {"simulated_source", o.source >= 0 ? Json(o.source) : Json(nullptr)}});
  return rows;
}

Json GapJson(const GapReport& g) {
  Json trends = Json::array();
  for (const CovariateTrend& t : g.trends)
    trends.push_back({{"covariate", t.covariate},
                      {"observable", t.observable},
                      {"points", t.points},
                      {"slope_per_unit", Number(t.slope)},
                      {"slope_sigma", Number(t.slope_sigma)},
                      {"p_value", Number(t.p_value)},
                      {"significant", t.significant}});
  Json by = Json::array();
  for (const ObservableChi2& b : g.by_observable)
    by.push_back({{"observable", b.observable}, {"chi2", Number(b.chi2)}, {"count", b.count}});
  return {{"gap_detected", g.gap_detected},
          {"chi2", Number(g.chi2)},
          {"dof", g.dof},
          {"fitted_parameters", g.fitted_parameters},
          {"chi2_per_dof", Number(g.chi2_per_dof)},
          {"p_value", Number(g.p_value)},
          {"critical_chi2", Number(g.critical_chi2)},
          {"outlier_threshold", Number(g.outlier_threshold)},
          {"outliers", g.outliers},
          {"by_observable", by},
          {"trends", trends},
          {"summary", g.summary}};
}

Json CandidateJson(const DiagnosisRunInfo& info, const RankingEntry& e, int rank, bool winner) {
  const CandidateEffect& c = info.candidates[e.candidate];
  Json parameters = Json::array();
  for (size_t k = 0; k < c.parameters.size(); ++k)
    parameters.push_back({{"name", c.parameters[k].name},
                          {"unit", c.parameters[k].unit},
                          {"value", k < e.values.size() ? Number(e.values[k]) : Json(nullptr)},
                          {"lower", c.parameters[k].lower},
                          {"upper", c.parameters[k].upper},
                          {"probe", c.parameters[k].probe}});
  const std::string direction =
      e.values.empty() ? "" : EffectDirection(c.parameters[0], e.values[0]);
  return {{"rank", rank},
          {"effect", e.key},
          {"description", c.description},
          {"parameters", parameters},
          {"direction", direction},
          {"refit", e.simulated ? "simulated" : "linearised"},
          {"chi2", Number(e.chi2)},
          {"chi2_per_dof_after", Number(e.chi2_per_dof)},
          {"delta_bic", Number(e.evidence.delta_bic)},
          {"chi2_noise_sd", Number(e.evidence.chi2_noise_sd)},
          {"likelihood_ratio_p", Number(e.evidence.lr_p_value)},
          {"significant", e.evidence.significant},
          {"chi2_linearised", Number(e.chi2_linear)},
          {"delta_bic_linearised", Number(e.linear.delta_bic)},
          {"signature_match", Number(e.signature_match)},
          {"discrepancy_floor_single_run_scatters", Number(e.evidence.floor)},
          {"control", e.control},
          {"winner", winner},
          {"note", e.note}};
}

Json SeparatingJson(const std::vector<Observation>& obs, const SeparatingMeasurement& m) {
  if (m.observation < 0 || m.observation >= static_cast<int>(obs.size())) return nullptr;
  const Observation& o = obs[m.observation];
  return {{"observable", o.observable},
          {"condition", ConditionJson(o.condition)},
          {"experiment", o.experiment},
          {"name", o.name},
          {"prediction_first", Number(m.prediction_a)},
          {"prediction_second", Number(m.prediction_b)},
          {"difference_sigma", Number(m.difference_sigma)},
          {"sigma_shrink_first", Number(m.shrink_a)},
          {"sigma_shrink_second", Number(m.shrink_b)},
          {"lifts_valley", m.lifts_valley},
          {"separates", m.separates},
          {"description", m.description}};
}

Json StepJson(const DiagnosisRunInfo& info, const std::vector<Observation>& obs,
              const DiagnosisStep& s) {
  Json candidates = Json::array();
  int rank = 1;
  for (int i : s.ranking.order)
    candidates.push_back(CandidateJson(info, s.entries[i], rank++, i == s.ranking.winner));
  Json carried = Json::array();
  for (const ObservableShare& o : s.carried)
    carried.push_back({{"observable", o.observable},
                       {"chi2_gain_over_runner_up", Number(o.against_runner_up)},
                       {"chi2_gain_over_base", Number(o.against_base)}});
  return {{"candidates", candidates},
          {"winner", s.ranking.winner >= 0 ? Json(s.entries[s.ranking.winner].key) : Json(nullptr)},
          {"distinguished", s.ranking.distinguished},
          {"not_told_apart_from",
           s.ranking.tied >= 0 ? Json(s.entries[s.ranking.tied].key) : Json(nullptr)},
          {"law_not_told_apart_from", s.ranking.same_mechanism >= 0
                                          ? Json(s.entries[s.ranking.same_mechanism].key)
                                          : Json(nullptr)},
          {"control_first", s.ranking.control_first},
          {"separating_measurement",
           s.ranking.tied >= 0 ? SeparatingJson(obs, s.separating) : Json(nullptr)},
          {"message", s.ranking.message},
          {"observables_carried", carried},
          {"simulations", s.simulations},
          {"wall_time_s", s.wall_time_s}};
}

// A base fitted onto a bound against the effects that let it back inside (bound_step.h);
// null when no base parameter ended on a bound or no step compared them.
Json BoundJson(const DiagnosisRunInfo& info, const Diagnosis& d) {
  if (d.bound.verdict == BoundVerdict::kNotJudged) return nullptr;
  Json base = Json::array();
  for (size_t k = 0; k < info.base_names.size() && k < info.bound_effect_base_si.size(); ++k)
    base.push_back({{"name", info.base_names[k]}, {"value", Number(info.bound_effect_base_si[k])}});
  const bool control = d.bound.alternative >= 0 && !d.steps.empty();
  return {{"verdict", BoundVerdictName(d.bound.verdict)},
          {"parameters", d.bound_parameters},
          {"effect", d.bound_effect.empty() ? Json(nullptr) : Json(d.bound_effect)},
          {"effect_value", d.bound_effect.empty() ? Json(nullptr) : Number(d.bound_effect_value)},
          {"effect_base_parameters", base},
          {"effect_chi2_per_dof",
           d.bound_effect.empty() ? Json(nullptr) : Number(d.bound_effect_chi2_per_dof)},
          {"alternative",
           control ? d.steps.front().entries[d.bound.alternative].key : "base at its bound"},
          {"bic_gap", Number(d.bound.bic_gap)},
          {"tie_margin", Number(d.bound.within)},
          {"note", d.bound_note}};
}

// The screen without a gap (diagnosis.h step 2): the omnibus test's p beside the directed test
// of the step's winner, or of its best simulated candidate; null when no screen ran.
// Per candidate still open at the end, the smallest size its own test would have found
// (detection_limits.h); null where none lies within the parameter's range in that direction.
Json DetectionJson(const DiagnosisRunInfo& info, const Diagnosis& d) {
  Json effects = Json::array();
  for (const EffectDetection& e : d.detection_limits) {
    const EffectParameter& p = info.candidates[e.candidate].parameters[0];
    const double m = e.has_signature ? e.limit.magnitude : INFINITY;
    effects.push_back(
        {{"effect", info.candidates[e.candidate].key},
         {"parameter", p.name},
         {"unit", p.unit},
         {"smallest_detectable_increase", e.upper > 0 && m <= e.upper ? Number(m) : Json(nullptr)},
         {"smallest_detectable_decrease",
          e.lower < 0 && m <= -e.lower ? Number(-m) : Json(nullptr)},
         {"magnitude_at_power", Number(m)},
         {"magnitude_at_half_power", Number(e.has_signature ? e.limit.magnitude_half : INFINITY)},
         {"range", {Number(e.lower), Number(e.upper)}},
         {"critical_sd", Number(e.limit.critical)},
         {"signature_beyond_fit_sd_per_unit", Number(e.limit.projected_norm)},
         {"has_signature", e.has_signature}});
  }
  return {{"power", kDetectionPower},
          {"at", "the final fit, linearised (docs/diagnose/ranking.md)"},
          {"effects", effects}};
}

Json ScreenJson(const DiagnosisRunInfo& info, const Diagnosis& d) {
  if (!d.screened || d.steps.empty()) return nullptr;
  const DiagnosisStep& step = d.steps.front();
  const int best = DecidingEntry(step.ranking, step.entries);
  const double per_candidate =
      info.options.significance / static_cast<double>(std::max<size_t>(1, step.entries.size()));
  return {{"omnibus_chi2_p_value", Number(d.gap_before.p_value)},
          {"significance_per_candidate", Number(per_candidate)},
          {"best_candidate", best < 0 ? Json(nullptr) : Json(step.entries[best].key)},
          {"best_lr_p_value",
           best < 0 ? Json(nullptr) : Number(step.entries[best].evidence.lr_p_value)},
          {"best_refit", best < 0 ? Json(nullptr)
                         : Json(step.entries[best].simulated ? "simulated" : "linearised")},
          {"best_significant", best >= 0 && step.entries[best].evidence.significant}};
}

}  // namespace

Json DiagnosisJson(const DiagnosisRunInfo& info, const Diagnosis& d) {
  Json j;
  j["format"] = "demcal-diagnosis/1";
  j["termination"] = DiagnosisTerminationName(d.termination);
  j["message"] = d.message;
  j["gap_detected"] = d.gap_before.gap_detected;
  j["chi2_per_dof_before"] = Number(d.gap_before.chi2_per_dof);
  j["screen"] = ScreenJson(info, d);
  j["named_effect"] = d.named.empty() ? Json(nullptr) : Json(info.candidates[d.named.front()].key);
  Json named = Json::array(), signed_effects = Json::array();
  for (int c : d.named) named.push_back(info.candidates[c].key);
  for (const ActiveEffect& a : d.final_point.effects) {
    if (!d.Named(a.candidate))
      continue;  // a re-valued modelled parameter: revalued_parameters
    const EffectParameter& p = info.candidates[a.candidate].parameters[0];
    signed_effects.push_back({{"effect", info.candidates[a.candidate].key},
                              {"parameter", p.name},
                              {"unit", p.unit},
                              {"value", Number(a.values[0])},
                              {"direction", EffectDirection(p, a.values[0])}});
  }
  j["named_effects"] = named;
  // Per named effect, its mechanism and the other law of it the data did not tell apart (null:
  // none): "adhesion", "jkr_adhesion" when sjkr_cohesion fitted better but not decisively.
  Json mechanisms = Json::array();
  for (size_t k = 0; k < d.named.size(); ++k) {
    const int alternative = k < d.named_law_alternative.size() ? d.named_law_alternative[k] : -1;
    const CandidateEffect& c = info.candidates[d.named[k]];
    mechanisms.push_back({{"effect", c.key},
                          {"mechanism", c.mechanism.empty() ? c.key : c.mechanism},
                          {"law_not_told_apart_from", alternative >= 0
                                                          ? Json(info.candidates[alternative].key)
                                                          : Json(nullptr)}});
  }
  j["named_mechanisms"] = mechanisms;
  j["named_effects_signed"] = signed_effects;
  Json revalued = Json::array();  // model form: re-valued modelled parameters, never named
  for (const ActiveEffect& a : d.revalued) {
    const EffectParameter& p = info.candidates[a.candidate].parameters[0];
    revalued.push_back({{"effect", info.candidates[a.candidate].key},
                        {"parameter", p.name},
                        {"unit", p.unit},
                        {"value", Number(a.values[0])},
                        {"assumed", Number(p.assumed)},
                        {"direction", EffectDirection(p, a.values[0])}});
  }
  j["revalued_parameters"] = revalued;
  // An added effect that fitted within noise of a re-valuation of less than assumed
  // (revaluation.h, RevaluationSettlesTie): not named, tried again on the re-valued fit.
  if (d.revaluation_tie.candidate >= 0 && !d.revaluation_tie.values.empty()) {
    const EffectParameter& p = info.candidates[d.revaluation_tie.candidate].parameters[0];
    j["revaluation_tied_with"] = {{"effect", info.candidates[d.revaluation_tie.candidate].key},
                                  {"parameter", p.name},
                                  {"unit", p.unit},
                                  {"value", Number(d.revaluation_tie.values[0])},
                                  {"direction", EffectDirection(p, d.revaluation_tie.values[0])}};
  } else {
    j["revaluation_tied_with"] = nullptr;
  }
  j["chi2_per_dof_after"] = Number(d.gap_after.chi2_per_dof);
  j["after_fit"] = d.after_revalued ? "revalued_parameters"
                  : d.after_tied   ? "not_told_apart_worse"
                                   : "named_effects";
  Json tied_after = Json::array();  // each tied refit's χ²/dof; "after" is the larger
  for (size_t k = 0; k < d.tied_chi2_per_dof_after.size() && k < d.not_told_apart.size(); ++k)
    tied_after.push_back({{"effect", info.candidates[d.not_told_apart[k]].key},
                          {"chi2_per_dof_after", Number(d.tied_chi2_per_dof_after[k])}});
  j["not_told_apart_after"] = tied_after;
  const size_t tried = d.steps.empty() ? info.candidates.size() : d.steps.front().entries.size();
  j["discrepancy_floor"] = {
      {"fixed_single_run_scatters", info.options.discrepancy_floor},
      {"estimated_single_run_scatters_before", Number(d.floor_before)},
      {"estimated_single_run_scatters_after", Number(d.floor_after)},
      {"estimator", "Paule-Mandel: the floored chi2 equals n - p (docs/diagnose.md)"},
      {"significance_per_candidate",
       info.options.significance / static_cast<double>(std::max<size_t>(1, tried))}};
  j["gap_detected_after"] = d.gap_after.gap_detected;
  j["detection_limits"] = DetectionJson(info, d);
  j["candidates"] =
      d.steps.empty() ? Json::array() : StepJson(info, d.before, d.steps.front())["candidates"];
  Json tie = Json::array();
  for (int c : d.not_told_apart) tie.push_back(info.candidates[c].key);
  if (d.bound.verdict == BoundVerdict::kNotToldApart) tie.push_back(d.bound_parameters);
  j["not_told_apart"] = tie;
  j["separating_measurement"] =
      d.not_told_apart.empty() ? Json(nullptr) : SeparatingJson(d.before, d.separating);
  j["control_guard"] = d.control_note.empty() ? Json(nullptr) : Json(d.control_note);
  Json steps = Json::array();
  for (const DiagnosisStep& s : d.steps) steps.push_back(StepJson(info, d.before, s));
  j["steps"] = steps;
  j["gap_before"] = GapJson(d.gap_before);
  j["gap_after"] = GapJson(d.gap_after);
  j["residuals_before"] = ResidualTable(d.before);
  j["residuals_after"] = ResidualTable(d.after);
  Json undetermined = Json::array();
  for (const calibrate::UndeterminedDirection& u : d.base_identifiability.undetermined)
    undetermined.push_back({{"description", u.description},
                            {"singular_value", Number(u.singular_value)},
                            {"unit_direction", u.unit_direction}});
  Json singular = Json::array();
  for (double s : d.base_identifiability.singular_values) singular.push_back(Number(s));
  Json base_steps = Json::array();
  for (const BaseStepRecord& r : d.base_steps)
    base_steps.push_back({{"unit", r.unit},
                          {"fraction", r.fraction},
                          {"chi2_before", Number(r.chi2_before)},
                          {"chi2_predicted", Number(r.chi2_predicted)},
                          {"chi2_simulated", Number(r.chi2_simulated)},
                          {"predicted_drop_threshold", Number(r.threshold)},
                          {"accepted", r.accepted}});
  j["base_calibration"] = {{"termination", d.base.termination},
                           {"message", d.base.message},
                           {"settled", d.base.settled},
                           {"max_evaluations", d.base.max_evaluations},
                           {"budget_scale", d.base_budget_scale},
                           {"summary", d.base_summary},
                           {"linearised_steps", base_steps},
                           {"identifiable", d.base_identifiability.Identifiable()},
                           {"singular_values", singular},
                           {"undetermined", undetermined},
                           {"at_bound", d.base_at_bound},
                           {"bound_alternative", BoundJson(info, d)}};
  Json phases = Json::array();
  for (const PhaseTime& p : d.phases)
    phases.push_back(
        {{"phase", p.phase}, {"simulations", p.simulations}, {"wall_time_s", p.wall_time_s}});
  j["simulations"] = d.simulations;
  j["simulations_reused"] = d.simulations_reused;
  j["phases"] = phases;
  j["wall_time_s"] = d.wall_time_s;
  j["provenance"] = {{"demcal_version", kVersion},
                     {"study", info.study},
                     {"description", info.description},
                     {"synthetic_data", info.synthetic},
                     {"data_provenance", info.data_provenance},
                     {"fidelity", info.fidelity},
                     {"seed", info.seed},
                     {"replicates", info.replicates},
                     {"significance", info.options.significance},
                     {"discrepancy_floor_single_run_scatters", info.options.discrepancy_floor},
                     {"refits_per_step", info.options.dem_refits},
                     {"max_effects", info.options.max_effects},
                     {"extra_refits", info.options.extra_refits},
                     {"screen_without_gap", info.options.screen},
                     {"subject_species", info.context.species},
                     {"subject_material", info.context.material},
                     {"wall_materials", info.context.wall_materials},
                     {"coating_column", info.context.coating_column}};
  if (!info.journal_error.empty()) j["journal_error"] = info.journal_error;
  return j;
}

Json DiagnosedParamsJson(const DiagnosisRunInfo& info, const Diagnosis& d) {
  Json base = Json::array();
  for (size_t k = 0; k < info.base_names.size(); ++k)
    base.push_back(
        {{"name", info.base_names[k]},
         {"value", k < info.base_after_si.size() ? Number(info.base_after_si[k]) : Json(nullptr)}});
  Json effects = Json::array();
  for (const ActiveEffect& a : d.final_point.effects) {
    const CandidateEffect& c = info.candidates[a.candidate];
    Json values = Json::object();
    for (size_t k = 0; k < a.values.size() && k < c.parameters.size(); ++k)
      values[c.parameters[k].name] = Number(a.values[k]);
    effects.push_back({{"effect", c.key},
                       {"description", c.description},
                       {"role", d.Named(a.candidate) ? "named" : "revalued"},
                       {"values", values}});
  }
  return {{"format", "demcal-params/1"},
          {"parameters", base},
          {"effects", effects},
          {"note",
           "base parameters of the study refitted with the named effects and the re-valued "
           "modelled parameters (role; docs/diagnose.md); "
           "effect values are increments on the experiment files' model"},
          {"provenance",
           {{"study", info.study},
            {"fidelity", info.fidelity},
            {"seed", info.seed},
            {"replicates", info.replicates},
            {"demcal_version", kVersion}}}};
}

}  // namespace demcal::diagnose
