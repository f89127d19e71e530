// Parameters of a study: pair properties that are global, apply under a condition ("when"), or
// follow a curve over a covariate; constraints between them; the clump-count outer loop.
#include <algorithm>

#include "objectives/common/input_limits.h"
#include "workflow/calibration/study_sections.h"

namespace demcal::workflow {

namespace limits = objectives::limits;
namespace {

int MaterialIndex(const core::Scene& model, const std::string& name) {
  for (size_t k = 0; k < model.materials.size(); ++k)
    if (model.materials[k].name == name) return static_cast<int>(k);
  return -1;
}

// "materials": two names of the first experiment's model.
bool ParsePair(JsonFields& f, const core::Scene& model, std::pair<std::string, std::string>* names,
               int* i, int* j) {
  const nlohmann::json* list = f.Array("materials", kRequired);
  if (!f.ok()) return false;
  if (list->size() != 2 || !(*list)[0].is_string() || !(*list)[1].is_string())
    return f.Fail("materials", "must be two material names, e.g. [\"BP\", \"BP\"]"), false;
  *names = {(*list)[0].get<std::string>(), (*list)[1].get<std::string>()};
  *i = MaterialIndex(model, names->first);
  *j = MaterialIndex(model, names->second);
  if (*i < 0 || *j < 0) return f.Fail("materials", "names a material the experiment file does not define"), false;
  return true;
}

void ParseBounds(JsonFields& f, calibrate::Parameter* p, Range range) {
  f.Number("min", &p->lower, kRequired, range);
  f.Number("max", &p->upper, kRequired, range);
  p->start = 0.5 * (p->lower + p->upper);
  f.Number("start", &p->start, kOptional, range);
  f.Bool("log_scale", &p->log_scale, kOptional);
}

void ParseCurve(const nlohmann::json& j, const std::string& path, calibrate::ParameterCurve curve,
                StudyFile* study, JsonStatus* status) {
  JsonFields f(j, path, {"covariate", "form", "coefficients"}, status);
  std::string form = "linear";
  f.String("covariate", &curve.covariate, kRequired);
  f.String("form", &form, kOptional, calibrate::CurveFormKeys());
  const nlohmann::json* coefficients = f.Array("coefficients", kRequired);
  if (!f.ok()) return;
  calibrate::CurveFormFromKey(form, &curve.form);
  const size_t need = calibrate::CurveCoefficientCount(curve.form);
  if (coefficients->size() != need)
    return f.Fail("coefficients", "a " + form + " curve has " + std::to_string(need) + " coefficients");
  const int index = static_cast<int>(study->space.curves.size());
  for (size_t k = 0; k < need && f.ok(); ++k) {
    JsonFields c((*coefficients)[k], IndexPath(f.PathOf("coefficients"), k),
                 {"name", "min", "max", "start", "log_scale"}, status);
    calibrate::Parameter p{.property = curve.property, .material_i = curve.material_i,
                           .material_j = curve.material_j};
    c.String("name", &p.name, kRequired);
    ParseBounds(c, &p, Range::Closed(-1e6, 1e6));
    p.curve = index;
    curve.coefficients.push_back(static_cast<int>(study->space.parameters.size()));
    study->space.parameters.push_back(p);
    study->parameter_materials.push_back(study->curve_materials.back());
    study->parameter_paths.push_back(c.path());
  }
  study->space.curves.push_back(curve);
  study->curve_paths.push_back(path);
}

int ParameterIndex(const StudyFile& study, const std::string& name) {
  for (size_t k = 0; k < study.space.parameters.size(); ++k)
    if (study.space.parameters[k].name == name) return static_cast<int>(k);
  return -1;
}

}  // namespace

void ParseStudyParameter(const nlohmann::json& j, const std::string& path, StudyFile* study,
                         JsonStatus* status) {
  JsonFields f(j, path, {"name", "property", "materials", "min", "max", "start", "log_scale", "when", "curve"},
               status);
  std::string name, property;
  f.String("name", &name, kRequired);
  f.String("property", &property, kRequired,
           {"sliding_friction", "rolling_friction", "restitution", "interfacial_energy_J_m2",
            "cohesion_energy_density_J_m3", "aspect_ratio"});
  std::pair<std::string, std::string> names;
  int mi = 0, mj = 0;
  if (!f.ok() || !ParsePair(f, study->experiment().model, &names, &mi, &mj)) return;
  calibrate::PairProperty prop;
  calibrate::CalibratedPropertyFromKey(property, &prop);
  if (const nlohmann::json* curve = f.Object("curve", kOptional)) {
    if (f.Has("min") || f.Has("max") || f.Has("start") || f.Has("when"))
      return f.Fail("curve", "a curve's bounds belong to its coefficients; drop min/max/start/when");
    study->curve_materials.push_back(names);
    return ParseCurve(*curve, f.PathOf("curve"), {name, prop, mi, mj}, study, status);
  }
  calibrate::Parameter p{.name = name, .property = prop, .material_i = mi, .material_j = mj};
  ParseBounds(f, &p, Range::Closed(0, 1e3));
  if (const nlohmann::json* when = f.Object("when", kOptional); when && f.ok())
    ParseCondition(*when, f.PathOf("when"), &p.when, status);
  if (!f.ok()) return;
  study->space.parameters.push_back(p);
  study->parameter_materials.push_back(names);
  study->parameter_paths.push_back(path);
}

void ParseStudyConstraint(const nlohmann::json& j, const std::string& path, StudyFile* study,
                          JsonStatus* status) {
  JsonFields f(j, path, {"non_decreasing"}, status);
  const nlohmann::json* list = f.Array("non_decreasing", kRequired);
  if (!f.ok()) return;
  std::vector<int> chain;
  for (const nlohmann::json& name : *list) {
    const int k = name.is_string() ? ParameterIndex(*study, name.get<std::string>()) : -1;
    if (k < 0) return f.Fail("non_decreasing", "must list names of the study's parameters");
    chain.push_back(k);
  }
  if (chain.size() < 2) return f.Fail("non_decreasing", "needs at least two parameters");
  study->space.non_decreasing.push_back(chain);
  study->constraint_paths.push_back(f.PathOf("non_decreasing"));
}

void ParseClumpCount(const nlohmann::json& j, const std::string& path, StudyFile* study,
                     JsonStatus* status) {
  JsonFields f(j, path, {"species", "semi_axes", "counts"}, status);
  ClumpCountSearch& c = study->clump_count;
  f.String("species", &c.species, kRequired);
  f.Vector("semi_axes", &c.semi_axes, kRequired);
  if (!f.ok()) return;
  if (std::string why; !core::CheckEllipsoidSemiAxes(c.semi_axes, &why))
    return f.Fail("semi_axes", why);
  std::vector<int64_t> counts;
  f.Integers("counts", &counts, kRequired, Range::Of(limits::kClumpSpheres));
  if (!f.ok()) return;
  c.counts.assign(counts.begin(), counts.end());  // each within kClumpSpheres, so fits an int
  if (c.counts.empty() || !std::is_sorted(c.counts.begin(), c.counts.end()) ||
      std::adjacent_find(c.counts.begin(), c.counts.end()) != c.counts.end())
    return f.Fail("counts", "must be a non-empty ascending list without repeats");
  for (const StudyExperiment& e : study->experiments) {
    bool found = false;
    for (const core::Species& s : e.file.model.species) found = found || s.name == c.species;
    if (!found) return f.Fail("species", "'" + c.species + "' is not a species of " + e.path);
  }
}

}  // namespace demcal::workflow
