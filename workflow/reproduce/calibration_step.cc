#include "workflow/reproduce/calibration_step.h"

#include <cmath>
#include <filesystem>
#include <limits>

#include "workflow/calibration/run_study.h"
#include "outputs/exit_codes.h"
#include "files/json_document.h"

namespace demcal::workflow {
namespace {

namespace fs = std::filesystem;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

double Num(const nlohmann::json& j, const char* key) {
  return j.contains(key) && j[key].is_number() ? j[key].get<double>() : kNaN;
}

// " at coating_PEG_wt_pct 0.5" (empty for no condition).
std::string ConditionText(const nlohmann::json& conditions) {
  std::string text;
  for (const auto& [k, v] : conditions.items())
    text += (text.empty() ? " at " : ", ") + k + " " + (v.is_string() ? v.get<std::string>() : v.dump());
  return text;
}

nlohmann::ordered_json StudyJson(const CalibrationStep& s) {
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
  if (!s.clump_counts.empty())
    study["clump_count"] = {{"species", s.material_a}, {"semi_axes", s.semi_axes},
                            {"counts", s.clump_counts}};
  return study;
}

// result.json of the run (of the chosen count with a clump loop).
bool ReadOutcome(const CalibrationStep& step, CalibrationOutcome* o, std::string* error) {
  o->result_dir = step.dir;
  if (!step.clump_counts.empty()) {
    nlohmann::json table;
    if (!ReadJsonFile(step.dir + "/clump_count.json", "clump count table", &table, error))
      return false;
    o->clump_count = table["chosen"].is_number() ? table["chosen"].get<int>() : 0;
    int shown = o->clump_count > 0 ? o->clump_count : step.clump_counts.back();
    o->result_dir = step.dir + "/clumps_" + std::to_string(shown);
  }
  nlohmann::json r;
  if (!ReadJsonFile(o->result_dir + "/result.json", "calibration result", &r, error)) return false;
  const nlohmann::json& termination = r.contains("termination") ? r["termination"] : nlohmann::json();
  if (!termination.is_string() ||
      !calibrate::ParseTermination(termination.get<std::string>(), &o->termination))
    return *error = o->result_dir + "/result.json: no known termination", false;
  o->message = r.value("message", "");
  if (r.contains("parameters") && !r["parameters"].empty()) {
    o->value = Num(r["parameters"][0], "value");
    o->sigma = Num(r["parameters"][0], "sigma");
  }
  if (r.contains("targets") && !r["targets"].empty()) {
    const auto& t = r["targets"][0];
    o->measured = Num(t, "measured");
    o->uncertainty = Num(t, "uncertainty");
    o->simulated = Num(t, "simulated");
    o->sem = Num(t, "sem");
  }
  if (r.contains("provenance") && r["provenance"].contains("targets") &&
      !r["provenance"]["targets"].empty())
    o->provenance = r["provenance"]["targets"][0].value("provenance", "");
  return true;
}

nlohmann::json NumOrNull(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(); }

}  // namespace

nlohmann::json CalibrationOutcome::ToJson() const {
  return {{"exit_code", exit_code}, {"termination", calibrate::TerminationName(termination)}, {"message", message},
          {"value", NumOrNull(value)}, {"sigma", NumOrNull(sigma)}, {"measured", NumOrNull(measured)},
          {"uncertainty", NumOrNull(uncertainty)}, {"simulated", NumOrNull(simulated)},
          {"sem", NumOrNull(sem)}, {"provenance", provenance}, {"clump_count", clump_count},
          {"result_dir", result_dir}};
}

bool RunCalibrationStep(const ReproduceContext& ctx, const CalibrationStep& step,
                        CalibrationOutcome* out, std::string* error) {
  std::error_code ec;
  fs::create_directories(step.dir, ec);
  if (ec) return *error = "cannot create '" + step.dir + "': " + ec.message(), false;
  const std::string study_path = step.dir + "/study.json";
  if (!WriteJsonFile(study_path, StudyJson(step), error)) return false;
  CalibrateOptions options;
  options.study_path = study_path;
  options.out_dir = step.dir;
  options.quick = ctx.quick;
  options.threads = ctx.threads;
  options.quiet = ctx.quiet;
  *out = CalibrationOutcome{};
  out->exit_code = RunCalibrate(options, *ctx.log);
  if (out->exit_code != kExitOk && out->exit_code != kExitRunFailed) {
    *error = "calibration in '" + step.dir + "' failed with exit code " +
             std::to_string(out->exit_code) + " (its message is above)";
    return false;
  }
  return ReadOutcome(step, out, error);
}

}  // namespace demcal::workflow
