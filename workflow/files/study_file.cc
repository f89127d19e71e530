#include "workflow/files/study_file.h"

#include <filesystem>
#include <sstream>

#include "workflow/files/json_document.h"
#include "workflow/files/json_fields.h"
#include "workflow/files/measurement_table.h"

namespace demcal::workflow {
namespace {

namespace fs = std::filesystem;

// Paths in a study are relative to the study file's folder.
std::string Resolve(const std::string& study, const std::string& path) {
  return fs::path(path).is_absolute() ? path : (fs::path(study).parent_path() / path).lexically_normal().string();
}

int MaterialIndex(const core::Scene& model, const std::string& name) {
  for (size_t k = 0; k < model.materials.size(); ++k)
    if (model.materials[k].name == name) return static_cast<int>(k);
  return -1;
}

void ParseParameter(const nlohmann::json& j, const std::string& path, const core::Scene& model,
                    calibrate::Parameter* p, JsonStatus* status) {
  JsonFields f(j, path, {"name", "property", "materials", "min", "max", "start", "log_scale"}, status);
  std::string property;
  f.String("name", &p->name, kRequired);
  f.String("property", &property, kRequired,
           {"sliding_friction", "rolling_friction", "restitution", "interfacial_energy_J_m2"});
  f.Number("min", &p->lower, kRequired, Range::Closed(0, 1e3));
  f.Number("max", &p->upper, kRequired, Range::Closed(0, 1e3));
  p->start = 0.5 * (p->lower + p->upper);
  f.Number("start", &p->start, kOptional, Range::Closed(0, 1e3));
  f.Bool("log_scale", &p->log_scale, kOptional);
  if (!f.ok()) return;
  calibrate::PairPropertyFromKey(property, &p->property);
  const nlohmann::json* names = f.Array("materials", kRequired);
  if (!f.ok()) return;
  if (names->size() != 2 || !(*names)[0].is_string() || !(*names)[1].is_string())
    return f.Fail("materials", "must be two material names, e.g. [\"BP\", \"BP\"]");
  p->material_i = MaterialIndex(model, (*names)[0]);
  p->material_j = MaterialIndex(model, (*names)[1]);
  if (p->material_i < 0 || p->material_j < 0)
    f.Fail("materials", "names a material the experiment file does not define");
}

void ParseMeasurement(const nlohmann::json& j, const std::string& path, const std::string& study,
                      const std::string& observable, StudyFile* out, JsonStatus* status) {
  JsonFields f(j, path, {"dataset", "material", "coating_PEG_wt_pct", "uncertainty_deg", "uncertainty_note"},
               status);
  std::string dataset, material;
  double coating = 0;
  f.String("dataset", &dataset, kRequired);
  f.String("material", &material, kRequired);
  f.Number("coating_PEG_wt_pct", &coating, kOptional, Range::Closed(0, 100, "wt%"));
  double assumed = 0;
  f.Number("uncertainty_deg", &assumed, kOptional, Range::LeftOpen(0, 90, "deg"));
  f.String("uncertainty_note", &out->measurement_note, kOptional);
  if (!f.ok()) return;
  MeasurementTable table;
  std::string error;
  if (!LoadMeasurementTable(Resolve(study, dataset), &table, &error)) return f.Fail("dataset", error);
  std::ostringstream w;
  w << coating;
  const MeasurementRow* row = table.Find(observable, material, {{"coating_PEG_wt_pct", w.str()}}, &error);
  if (!row) return f.Fail("dataset", error);
  out->measurement.observable = observable;
  out->measurement.value = row->value;
  out->measurement.uncertainty = row->uncertainty;
  out->measurement.source = table.path + " line " + std::to_string(row->line) + " (" + row->source + ")";
  if (assumed > 0 && !row->HasUncertainty()) out->measurement.uncertainty = assumed;
  else if (!row->HasUncertainty())
    f.Fail("uncertainty_deg", "required: the dataset row reports no standard deviation, so the "
                              "study must state the uncertainty it assumes (deg, > 0)");
}

void ParseOptimiser(const nlohmann::json& j, const std::string& path,
                    calibrate::CalibrationOptions* o, JsonStatus* status) {
  JsonFields f(j, path, {"name", "max_evaluations", "unit_tolerance"}, status);
  f.String("name", &o->optimiser, kOptional, calibrate::OptimiserNames());
  int64_t budget = o->optimiser_options.max_evaluations;
  f.Integer("max_evaluations", &budget, kOptional, Range::Closed(1, 100000));
  o->optimiser_options.max_evaluations = static_cast<int>(budget);
  f.Number("unit_tolerance", &o->optimiser_options.unit_tolerance, kOptional, Range::Open(0, 0.5));
}

}  // namespace

bool LoadStudyFile(const std::string& path, StudyFile* out, std::string* error) {
  nlohmann::json doc;
  if (!ReadJsonFile(path, "study file", &doc, error)) return false;
  out->source = path;
  JsonStatus status;
  JsonFields f(doc, "", {"format", "description", "experiment_file", "measurement", "parameters",
                         "optimiser", "replicates", "seed"}, &status);
  std::string format, experiment;
  f.String("format", &format, kRequired, {kStudyFormat});
  f.String("description", &out->description, kOptional);
  f.String("experiment_file", &experiment, kRequired);
  int64_t replicates = 0;
  f.Integer("replicates", &replicates, kOptional, Range::Closed(1, 1000));
  out->replicates = static_cast<int>(replicates);
  out->has_seed = f.Has("seed");
  f.Unsigned("seed", &out->seed, kOptional);
  if (!status.ok()) return *error = path + ": " + status.message(), false;
  out->experiment_path = Resolve(path, experiment);
  if (!LoadExperimentFile(out->experiment_path, &out->experiment, error)) return false;
  if (out->experiment.experiment != "aor")
    return *error = path + ": experiment_file: calibration fits the angle of repose ('aor' "
                           "experiments) so far, not '" + out->experiment.experiment + "'", false;
  const nlohmann::json* m = f.Object("measurement", kRequired);
  if (m) ParseMeasurement(*m, "measurement", path, "angle_deg", out, &status);
  const nlohmann::json* params = f.Array("parameters", kRequired);
  for (size_t k = 0; status.ok() && params && k < params->size(); ++k) {
    out->space.parameters.emplace_back();
    ParseParameter((*params)[k], IndexPath("parameters", k), out->experiment.model,
                   &out->space.parameters.back(), &status);
  }
  if (const nlohmann::json* o = f.Object("optimiser", kOptional); o && status.ok())
    ParseOptimiser(*o, "optimiser", &out->options, &status);
  if (!status.ok()) return *error = path + ": " + status.message(), false;
  std::string invalid;
  if (!out->space.IsValid(out->experiment.model, &invalid)) return *error = path + ": " + invalid, false;
  if (out->options.optimiser == "bracket" && out->space.Size() != 1)
    return *error = path + ": optimiser.name: 'bracket' fits exactly one parameter; use "
                           "nlopt_bobyqa, nlopt_cobyla or nlopt_neldermead", false;
  return true;
}

}  // namespace demcal::workflow
