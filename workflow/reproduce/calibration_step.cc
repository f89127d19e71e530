#include "workflow/reproduce/calibration_step.h"

#include <cmath>
#include <filesystem>

#include "objectives/farm/farm.h"
#include "workflow/calibration/calibration_outputs.h"
#include "workflow/calibration/run_study.h"
#include "outputs/exit_codes.h"
#include "files/json_document.h"

namespace demcal::workflow {
namespace {

namespace fs = std::filesystem;

// " at coating_PEG_wt_pct 0.5" (empty for no condition).
std::string ConditionText(const nlohmann::json& conditions) {
  std::string text;
  for (const auto& [k, v] : conditions.items())
    text += (text.empty() ? " at " : ", ") + k + " " + (v.is_string() ? v.get<std::string>() : v.dump());
  return text;
}

// bracket_points only when above 1: a one-point study's file, and with it its journal's study
// hash, is the same as without the option, so its journal resumes.
nlohmann::ordered_json StudyJson(const CalibrationStep& s, int bracket_points) {
  nlohmann::ordered_json measurement{{"table", fs::absolute(s.table).string()},
                                     {"material", s.material},
                                     {"conditions", s.conditions}};
  measurement["uncertainty"] = s.uncertainty;
  measurement["uncertainty_note"] = s.uncertainty_note;
  nlohmann::ordered_json study{
      {"format", "demcal-study/2"},
      {"description", "written by demcal reproduce: " + s.parameter + " against the repose angle "
                      "of " + s.material + " " + s.conditions.dump()},
      {"targets", {{{"name", s.material + " angle" + ConditionText(s.conditions)},
                    {"experiment_file", fs::absolute(s.experiment_file).string()},
                    {"observable", "angle_deg"},
                    {"measurement", measurement}}}},
      {"parameters", {{{"name", s.parameter}, {"property", s.property},
                       {"materials", {s.material_a, s.material_b}}, {"min", s.min},
                       {"max", s.max}, {"start", s.start}}}},
      {"optimiser", {{"name", "bracket"}, {"max_evaluations", s.max_evaluations}}},
      {"replicates", s.replicates}};
  // A k-section spends up to k candidates a round: the same number of rounds needs k times the
  // budget (a held species' one candidate stays one: no search).
  if (bracket_points > 1) {
    study["optimiser"]["bracket_points"] = bracket_points;
    if (s.max_evaluations > 1)
      study["optimiser"]["max_evaluations"] = s.max_evaluations * bracket_points;
  }
  if (!s.clump_counts.empty())
    study["clump_count"] = {{"species", s.material_a}, {"semi_axes", s.semi_axes},
                            {"counts", s.clump_counts}};
  return study;
}

// The outcome of a step from the typed result (of the chosen count with a clump loop).
void FillOutcome(const StudyFile& study, const CalibrationResult& r, CalibrationOutcome* o) {
  o->termination = r.termination;
  o->message = r.message;
  o->clump_count = r.clump_count;
  o->result_dir = r.out_dir;
  if (!r.parameters.empty()) {
    o->value = r.parameters[0].value;
    o->sigma = r.parameters[0].sigma;
  }
  if (!r.targets.empty()) {
    const CalibratedTarget& t = r.targets[0];
    o->measured = t.measured;
    o->uncertainty = t.uncertainty;
    o->simulated = t.simulated;
    o->sem = t.sem;
  }
  if (!study.targets.empty()) o->provenance = study.targets[0].provenance;
  o->local_crossing = r.summary.local_crossing;
  TakeLine(r.summary.local_crossing_value, r.summary.local_crossing_sigma, o);
}

}  // namespace

void TakeLine(double value, double sigma, CalibrationOutcome* o) {
  if (o->termination == calibrate::Termination::kWithinNoise || !o->local_crossing.fitted) return;
  o->by_line = true;
  o->value = value;
  o->sigma = sigma;
  o->simulated = o->measured;  // the line's value at its crossing
  o->sem = o->local_crossing.residual_sigma * o->uncertainty;
}

bool CalibrationOutcome::Matched() const {
  return termination == calibrate::Termination::kWithinNoise || (by_line && local_crossing.matched);
}

std::string CalibrationOutcome::MatchText() const {
  if (termination == calibrate::Termination::kWithinNoise) return "";
  if (by_line) return local_crossing.message;
  return std::string("not matched: ") + calibrate::TerminationName(termination) + ": " + message;
}

nlohmann::json CalibrationOutcome::ToJson() const {
  return {{"exit_code", exit_code}, {"termination", calibrate::TerminationName(termination)}, {"message", message},
          {"value", NumOrNull(value)}, {"sigma", NumOrNull(sigma)}, {"measured", NumOrNull(measured)},
          {"uncertainty", NumOrNull(uncertainty)}, {"simulated", NumOrNull(simulated)},
          {"sem", NumOrNull(sem)}, {"provenance", provenance}, {"clump_count", clump_count},
          {"result_dir", result_dir},
          {"matched", Matched()}, {"by_line", by_line},
          {"local_crossing", LocalCrossingJson(local_crossing, by_line ? value : NAN, by_line ? sigma : NAN)}};
}

bool CheckCalibrationStep(const CalibrationStep& step, std::string* error) {
  StudyFile study;
  // Every path in the document is absolute: the name only heads the message, stripped below.
  const std::string name = "study";
  if (ParseStudyJson(nlohmann::json::parse(StudyJson(step, 1).dump()), name, &study, error))
    return true;
  if (error->rfind(name + ": ", 0) == 0) error->erase(0, name.size() + 2);
  return false;
}

bool RunCalibrationStep(const ReproduceContext& ctx, const CalibrationStep& step,
                        CalibrationOutcome* out, std::string* error) {
  const bool writer = objectives::farm::IsManager();  // under mpirun, only rank 0 writes
  std::error_code ec;
  if (writer) fs::create_directories(step.dir, ec);
  if (ec) return *error = "cannot create '" + step.dir + "': " + ec.message(), false;
  const std::string study_path = step.dir + "/study.json";
  const nlohmann::ordered_json document = StudyJson(step, ctx.bracket_points);
  if (writer && !WriteJsonFile(study_path, document, error)) return false;  // what ran
  *out = CalibrationOutcome{};
  StudyFile study;
  std::string refused;
  if (!ParseStudyJson(nlohmann::json::parse(document.dump()), study_path, &study, &refused)) {
    *ctx.log << "error: " << refused << "\n";
    out->exit_code = kExitInvalidInput;
  } else {
    const CalibrateSettings settings{
        .out_dir = step.dir, .quick = ctx.quick, .threads = ctx.threads, .quiet = ctx.quiet};
    const CalibrationResult result = CalibrateStudy(study, settings, *ctx.log);
    out->exit_code = ExitCodeOf(result.status);
    FillOutcome(study, result, out);
  }
  if (out->exit_code == kExitOutputError) {  // "cannot write": reproduce exits 4 on it
    *error = "calibration in '" + step.dir + "' cannot write its journal or outputs (exit code 4; "
             "its message is above)";
    return false;
  }
  if (out->exit_code != kExitOk && out->exit_code != kExitRunFailed) {
    *error = "calibration in '" + step.dir + "' failed with exit code " +
             std::to_string(out->exit_code) + " (its message is above)";
    return false;
  }
  return true;
}

}  // namespace demcal::workflow
