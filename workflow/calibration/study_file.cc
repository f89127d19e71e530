#include "workflow/calibration/study_file.h"

#include <cmath>
#include <filesystem>

#include "experiments/experiment_registry.h"
#include "files/json_document.h"
#include "objectives/common/input_limits.h"
#include "workflow/calibration/study_sections.h"

namespace demcal::workflow {

namespace limits = objectives::limits;
namespace {

namespace fs = std::filesystem;

constexpr const char* kFormat1 = "demcal-study/1";
constexpr const char* kFormat2 = "demcal-study/2";

void ParseOptimiser(const nlohmann::json& j, const std::string& path,
                    calibrate::CalibrationOptions* o, JsonStatus* status) {
  JsonFields f(j, path,
               {"name", "max_evaluations", "unit_tolerance", "batch_size", "bracket_points", "seed"},
               status);
  f.String("name", &o->optimiser, kOptional, calibrate::OptimiserNames());
  int64_t budget = o->optimiser_options.max_evaluations, batch = o->optimiser_options.batch_size;
  int64_t points = o->optimiser_options.bracket_points;
  f.Integer("max_evaluations", &budget, kOptional, Range::Of(limits::kMaxEvaluations));
  f.Integer("batch_size", &batch, kOptional, Range::Of(limits::kBatchSize));
  f.Integer("bracket_points", &points, kOptional, Range::Of(limits::kBatchSize));
  o->optimiser_options.max_evaluations = static_cast<int>(budget);
  o->optimiser_options.batch_size = static_cast<int>(batch);
  o->optimiser_options.bracket_points = static_cast<int>(points);
  f.Number("unit_tolerance", &o->optimiser_options.unit_tolerance, kOptional,
           Range::Of(limits::kUnitTolerance));
  f.Unsigned("seed", &o->optimiser_options.seed, kOptional);
}

template <class Parse>
void ForEach(JsonFields& f, const std::string& key, Presence presence, Parse parse) {
  const nlohmann::json* list = f.Array(key, presence);
  for (size_t k = 0; f.ok() && list && k < list->size(); ++k) parse((*list)[k], IndexPath(key, k));
}

// Format 2: targets over several experiments and conditions.
void ParseFormat2(JsonFields& f, StudyFile* out, JsonStatus* status) {
  std::string table;
  f.String("measurements", &table, kOptional);
  if (!table.empty()) table = ResolveStudyPath(out->source, table);
  ForEach(f, "targets", kRequired, [&](const nlohmann::json& j, const std::string& p) {
    ParseStudyTarget(j, p, table, out, status);
  });
  if (f.ok() && out->targets.empty()) f.Fail("targets", "must list at least one target");
  ForEach(f, "candidate_targets", kOptional, [&](const nlohmann::json& j, const std::string& p) {
    ParseStudyCandidateTarget(j, p, out, status);
  });
}

// Format 1: one experiment file and one measured angle.
void ParseFormat1(JsonFields& f, StudyFile* out, JsonStatus* status) {
  std::string experiment;
  f.String("experiment_file", &experiment, kRequired);
  if (!f.ok()) return;
  StudyExperimentIndex(experiment, "experiment_file", out, status);
  if (f.ok() && out->experiment().experiment != "aor")
    f.Fail("experiment_file", "a demcal-study/1 fits the angle of repose ('aor' experiments); use "
                              "demcal-study/2 targets for other experiments");
  if (const nlohmann::json* m = f.Object("measurement", kRequired); m && f.ok())
    ParseLegacyMeasurement(*m, "measurement", out, status);
}

// The top-level keys only one format reads: the parser of the other would skip them silently,
// so a study mixing the two would run without the targets or measurement its author wrote.
void RefuseOtherFormatKeys(JsonFields& f, const std::string& format) {
  const bool first = format == kFormat1;
  const char* other = first ? kFormat2 : kFormat1;
  const std::vector<std::string> keys =
      first ? std::vector<std::string>{"measurements", "targets", "candidate_targets"}
            : std::vector<std::string>{"experiment_file", "measurement"};
  for (const std::string& key : keys)
    if (f.Has(key))
      return f.Fail(key, std::string("is a ") + other + " key, but this file is " + format +
                             ", which does not read it");
}

}  // namespace

std::string ResolveStudyPath(const std::string& study, const std::string& path) {
  return fs::path(path).is_absolute() ? path : (fs::path(study).parent_path() / path).lexically_normal().string();
}

void ParseCondition(const nlohmann::json& value, const std::string& path, calibrate::Condition* out,
                    JsonStatus* status) {
  for (const auto& [column, cell] : value.items()) {
    if (cell.is_number() && std::isfinite(cell.get<double>())) (*out)[column] = cell.dump();
    else if (cell.is_string() && !cell.get<std::string>().empty()) (*out)[column] = cell.get<std::string>();
    // (append, not "'" + string: GCC 12 gives a false -Wrestrict on that operator+)
    else return status->Fail(std::string("'").append(JoinPath(path, column))
                                 .append("' must be a number or a non-empty string"));
  }
}

int StudyExperimentIndex(const std::string& path, const std::string& json_path, StudyFile* study,
                         JsonStatus* status) {
  const std::string resolved = ResolveStudyPath(study->source, path);
  for (size_t k = 0; k < study->experiments.size(); ++k)
    if (study->experiments[k].path == resolved) return static_cast<int>(k);
  StudyExperiment e{resolved, {}};
  std::string error;
  if (!LoadExperimentFile(resolved, &e.file, &error)) return status->Fail("'" + json_path + "': " + error), 0;
  if (!FindExperimentKind(e.file.experiment) || !FindExperimentKind(e.file.experiment)->make_probe)
    return status->Fail("'" + json_path + "': experiment '" + e.file.experiment +
                        "' cannot be calibrated against yet (" +
                        JoinNames(CalibratableExperimentNames()) + ")"), 0;
  study->experiments.push_back(std::move(e));
  return static_cast<int>(study->experiments.size()) - 1;
}

bool ResolveSpaceFor(const StudyFile& study, const core::Scene& model, calibrate::ParameterSpace* out,
                     std::string* error) {
  *out = study.space;
  auto index = [&](const std::string& name) {
    for (size_t k = 0; k < model.materials.size(); ++k)
      if (model.materials[k].name == name) return static_cast<int>(k);
    return -1;
  };
  auto resolve = [&](const std::pair<std::string, std::string>& names, int* i, int* j) {
    *i = index(names.first), *j = index(names.second);
    if (*i < 0 || *j < 0) *error = "a parameter names material '" + names.first + "' or '" + names.second +
                                   "', which this experiment file does not define";
    return *i >= 0 && *j >= 0;
  };
  for (size_t k = 0; k < out->parameters.size(); ++k)
    if (!resolve(study.parameter_materials[k], &out->parameters[k].material_i, &out->parameters[k].material_j))
      return false;
  for (size_t k = 0; k < out->curves.size(); ++k)
    if (!resolve(study.curve_materials[k], &out->curves[k].material_i, &out->curves[k].material_j))
      return false;
  return true;
}

bool ParseStudyJson(const nlohmann::json& doc, const std::string& path, StudyFile* out,
                    std::string* error) {
  *out = StudyFile{};
  out->source = path;
  JsonStatus status;
  JsonFields f(doc, "", {"format", "description", "experiment_file", "measurement", "measurements",
                         "targets", "candidate_targets", "parameters", "constraints", "clump_count",
                         "optimiser", "replicates", "seed"}, &status);
  f.String("format", &out->format, kRequired, {kFormat1, kFormat2});
  f.String("description", &out->description, kOptional);
  int64_t replicates = 0;
  f.Integer("replicates", &replicates, kOptional, Range::Of(limits::kReplicates));
  out->replicates = static_cast<int>(replicates);
  out->has_seed = f.Has("seed");
  f.Unsigned("seed", &out->seed, kOptional);
  if (f.ok()) RefuseOtherFormatKeys(f, out->format);
  if (f.ok()) (out->format == kFormat1 ? ParseFormat1 : ParseFormat2)(f, out, &status);
  ForEach(f, "parameters", kRequired, [&](const nlohmann::json& j, const std::string& p) {
    ParseStudyParameter(j, p, out, &status);
  });
  ForEach(f, "constraints", kOptional, [&](const nlohmann::json& j, const std::string& p) {
    ParseStudyConstraint(j, p, out, &status);
  });
  if (const nlohmann::json* c = f.Object("clump_count", kOptional); c && status.ok())
    ParseClumpCount(*c, "clump_count", out, &status);
  if (const nlohmann::json* o = f.Object("optimiser", kOptional); o && status.ok())
    ParseOptimiser(*o, "optimiser", &out->options, &status);
  if (!status.ok()) return *error = path + ": " + status.message(), false;
  std::string invalid;
  for (const StudyExperiment& e : out->experiments) {
    calibrate::ParameterSpace resolved;
    if (!ResolveSpaceFor(*out, e.file.model, &resolved, &invalid) ||
        !resolved.IsValid(e.file.model, &invalid, out->parameter_paths))
      return *error = path + ": " + invalid + " (experiment file " + e.path + ")", false;
  }
  if (!CheckStudyEvaluable(*out, &invalid)) return *error = path + ": " + invalid, false;
  if (out->options.optimiser == "bracket" && out->space.Size() != 1)
    return *error = path + ": optimiser.name: 'bracket' fits exactly one parameter; use ceres, "
                           "differential_evolution or an nlopt_* optimiser", false;
  return true;
}

bool LoadStudyFile(const std::string& path, StudyFile* out, std::string* error) {
  nlohmann::json doc;
  return ReadJsonFile(path, "study file", &doc, error) && ParseStudyJson(doc, path, out, error);
}

}  // namespace demcal::workflow
