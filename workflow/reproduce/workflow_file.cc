#include "workflow/reproduce/workflow_file.h"

#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>

#include "calibrate/observable_registry.h"
#include "core/limits/physical_limits.h"
#include "core/math/number_text.h"
#include "files/json_document.h"
#include "files/json_fields.h"
#include "objectives/common/input_limits.h"
#include "workflow/reproduce/aspect_bounds.h"

namespace demcal::workflow {

namespace limits = objectives::limits;
namespace {

namespace fs = std::filesystem;
using Parse = std::function<void(const nlohmann::json&, const std::string&)>;

std::string Resolve(const std::string& file, const std::string& relative) {
  if (relative.empty() || fs::path(relative).is_absolute()) return relative;
  return (fs::path(file).parent_path() / relative).lexically_normal().string();
}

void ForEach(JsonFields& f, const std::string& key, Presence presence, const Parse& parse) {
  const nlohmann::json* a = f.Array(key, presence);
  if (!a) return;
  if (a->empty() && presence == kRequired) f.Fail(key, "must not be empty");
  for (size_t i = 0; i < a->size() && f.ok(); ++i) parse((*a)[i], IndexPath(f.PathOf(key), i));
}

// A list of numbers each in `range`, at least `min_size` of them.
void NumberList(JsonFields& f, const std::string& key, Presence presence, Range range,
                size_t min_size, std::vector<double>* out, JsonStatus* status) {
  const nlohmann::json* a = f.Array(key, presence);
  if (!a) return;
  if (a->size() < min_size) f.Fail(key, "needs at least " + std::to_string(min_size) + " numbers");
  out->clear();
  for (size_t i = 0; i < a->size() && status->ok(); ++i) {
    const std::string at = IndexPath(f.PathOf(key), i);
    if (!(*a)[i].is_number())
      status->Fail(at + ": expected a number, got " + JsonTypeName((*a)[i]));
    else if (!range.Contains((*a)[i].get<double>()))
      status->Fail(at + ": must be in " + range.Describe());
    else
      out->push_back((*a)[i].get<double>());
  }
}

// "aspect_ratio": {"min", "max", "start", "max_evaluations"}, within the clump builder's range.
void ParseAspectRatio(const nlohmann::json& j, const std::string& path, AspectRatioSearch* a,
                      JsonStatus* status) {
  JsonFields f(j, path, {"min", "max", "start", "max_evaluations"}, status);
  const Range range = Range::Of(core::limits::kClumpAspectRatio);
  f.Number("min", &a->min, kRequired, range);
  f.Number("max", &a->max, kRequired, range);
  if (f.ok() && !(a->min < a->max)) return f.Fail("max", "must be larger than min");
  a->start = 0.5 * (a->min + a->max);
  f.Number("start", &a->start, kOptional, Range::Closed(a->min, a->max));
  int64_t n = a->max_evaluations;
  // The bracket's first three candidates are the start and both bounds.
  f.Integer("max_evaluations", &n, kOptional, Range::Closed(3, 30));
  a->max_evaluations = static_cast<int>(n);
  a->enabled = f.ok();
}

// Every count n >= 2 needs aspect ratios in [min, max] at which its chain is a grain
// (aspect_bounds.h): its spheres stand apart and still touch.
void CheckCountRanges(const WorkflowSpecies& s, const std::string& path, JsonStatus* status) {
  const AspectRatioSearch& a = s.aspect_ratio;
  for (int n : s.clump_counts) {
    const double hi = ConnectedAspectLimit(n, a.min, a.max);
    const double lo = DistinctAspectLimit(n, a.min, hi);
    if (n < 2 || lo < hi) continue;
    const double apart = DistinctAspectLimit(n, core::limits::kClumpAspectRatio.lo,
                                             core::limits::kClumpAspectRatio.hi);
    const double touch = ConnectedAspectLimit(n, core::limits::kClumpAspectRatio.lo,
                                              core::limits::kClumpAspectRatio.hi);
    return status->Fail("field '" + path + "' [min, max] = [" + core::NumberText(a.min) + ", " +
                        core::NumberText(a.max) + "] holds no grain of " + std::to_string(n) +
                        " spheres: it must overlap [" + core::NumberText(apart) + ", " +
                        core::NumberText(touch) + "], where its spheres stand apart and touch");
  }
}

void ParseSpecies(const nlohmann::json& j, const std::string& path, const std::string& file,
                  WorkflowSpecies* s, JsonStatus* status) {
  JsonFields f(j, path, {"name", "experiment_file", "property", "min", "max", "start",
                         "clump_counts", "semi_axes", "hold", "aspect_ratio"}, status);
  f.String("name", &s->name, kRequired);
  f.String("experiment_file", &s->experiment_file, kRequired);
  s->experiment_file = Resolve(file, s->experiment_file);
  f.String("property", &s->property, kOptional, {"rolling_friction", "sliding_friction"});
  f.Number("min", &s->min, kRequired, Range::Closed(0, 10));
  f.Number("max", &s->max, kRequired, Range::Closed(0, 10));
  s->start = 0.5 * (s->min + s->max);
  f.Number("start", &s->start, kOptional, Range::Closed(0, 10));
  if (f.ok() && !(s->min < s->max && s->start >= s->min && s->start <= s->max))
    f.Fail("start", "needs min < max and min <= start <= max");
  f.Bool("hold", &s->hold, kOptional);
  std::vector<int64_t> counts;
  f.Integers("clump_counts", &counts, kOptional, Range::Of(limits::kClumpSpheres));
  if (f.ok() && f.Has("clump_counts") && counts.empty())
    f.Fail("clump_counts", "needs at least 1 number");
  s->clump_counts.assign(counts.begin(), counts.end());  // each within kClumpSpheres
  if (const nlohmann::json* a = f.Object("aspect_ratio", kOptional); a && f.ok()) {
    if (s->clump_counts.empty() || !s->hold)
      return f.Fail("aspect_ratio", "needs clump_counts and \"hold\": true (the aspect ratio is "
                                    "calibrated per clump count with the property held)");
    if (f.Has("semi_axes"))
      return f.Fail("semi_axes", "give either semi_axes (a fixed shape) or aspect_ratio (a "
                                 "calibrated one), not both");
    ParseAspectRatio(*a, f.PathOf("aspect_ratio"), &s->aspect_ratio, status);
    if (status->ok()) CheckCountRanges(*s, f.PathOf("aspect_ratio"), status);
    return;
  }
  NumberList(f, "semi_axes", s->clump_counts.empty() ? kOptional : kRequired,
             Range::LeftOpen(0, 1e3), 3, &s->semi_axes, status);
  if (std::string why; status->ok() && s->semi_axes.size() == 3 &&
                       !core::CheckEllipsoidSemiAxes(
                           {s->semi_axes[0], s->semi_axes[1], s->semi_axes[2]}, &why))
    f.Fail("semi_axes", why);
}

void ParseCoating(const nlohmann::json& j, const std::string& path, const std::string& file,
                  WorkflowCoating* c, JsonStatus* status) {
  JsonFields f(j, path, {"material", "experiment_file", "covariate", "levels_wt_pct",
                         "gamma_min_J_m2", "gamma_max_J_m2", "curve_form", "partners",
                         "partner_radii_m", "coated_radius_m"}, status);
  f.String("material", &c->material, kRequired);
  f.String("experiment_file", &c->experiment_file, kRequired);
  c->experiment_file = Resolve(file, c->experiment_file);
  f.String("covariate", &c->covariate, kOptional);
  NumberList(f, "levels_wt_pct", kRequired, Range::LeftOpen(0, 100), 1, &c->levels, status);
  f.Number("gamma_min_J_m2", &c->gamma_min_J_m2, kOptional, Range::Closed(0, 10, "J/m2"));
  f.Number("gamma_max_J_m2", &c->gamma_max_J_m2, kOptional, Range::LeftOpen(0, 10, "J/m2"));
  if (f.ok() && c->gamma_min_J_m2 >= c->gamma_max_J_m2)
    f.Fail("gamma_max_J_m2", "must be larger than gamma_min_J_m2");
  std::string form = "linear";
  f.String("curve_form", &form, kOptional, calibrate::CurveFormKeys());
  if (f.ok()) calibrate::CurveFormFromKey(form, &c->curve_form);
  if (const nlohmann::json* p = f.Array("partners", kRequired)) {
    for (size_t i = 0; i < p->size() && status->ok(); ++i) {
      if (!(*p)[i].is_string()) status->Fail(IndexPath(f.PathOf("partners"), i) + ": expected a string");
      else c->partners.push_back((*p)[i].get<std::string>());
    }
  }
  NumberList(f, "partner_radii_m", kRequired, Range::LeftOpen(0, 1, "m"), 1, &c->partner_radii_m,
             status);
  if (f.ok() && c->partner_radii_m.size() != c->partners.size())
    f.Fail("partner_radii_m", "needs one radius per partner");
  f.Number("coated_radius_m", &c->coated_radius_m, kRequired, Range::LeftOpen(0, 1, "m"));
}

void ParseCohesion(const nlohmann::json& j, const std::string& path,
                   calibrate::CohesionInputs* c, JsonStatus* status) {
  JsonFields f(j, path, {"gamma_J_m2", "youngs_real_Pa", "youngs_sim_Pa", "poisson_ratio",
                         "radius_m", "density_kg_m3", "reference_gamma_sim_J_m2"}, status);
  // The ranges `demcal cohesion` and the cohesion stage check: one table (input_limits.h).
  f.Number("gamma_J_m2", &c->gamma_J_m2, kRequired, Range::Of(limits::kCohesionGamma, "J/m2"));
  f.Number("youngs_real_Pa", &c->youngs_real_Pa, kRequired,
           Range::Of(limits::kCohesionYoungs, "Pa"));
  f.Number("youngs_sim_Pa", &c->youngs_sim_Pa, kRequired, Range::Of(limits::kCohesionYoungs, "Pa"));
  f.Number("poisson_ratio", &c->poisson_ratio, kRequired, Range::Of(limits::kCohesionPoisson));
  f.Number("radius_m", &c->radius_m, kRequired, Range::Of(limits::kCohesionRadius, "m"));
  f.Number("density_kg_m3", &c->density_kg_m3, kRequired,
           Range::Of(limits::kCohesionDensity, "kg/m3"));
  f.Number("reference_gamma_sim_J_m2", &c->reference_gamma_sim_J_m2, kOptional,
           Range::Of(limits::kCohesionGamma, "J/m2"));
}

void ParsePairOverride(const nlohmann::json& j, const std::string& path, PairOverride* o,
                       JsonStatus* status) {
  JsonFields f(j, path, {"materials", "property", "value", "note"}, status);
  if (const nlohmann::json* m = f.Array("materials", kRequired); m && f.ok()) {
    if (m->size() != 2 || !(*m)[0].is_string() || !(*m)[1].is_string() ||
        (*m)[0].get<std::string>().empty() || (*m)[1].get<std::string>().empty())
      return f.Fail("materials", "must be two material names, e.g. [\"BP\", \"EP\"]");
    o->material_a = (*m)[0].get<std::string>();
    o->material_b = (*m)[1].get<std::string>();
  }
  f.String("property", &o->property, kRequired, {"rolling_friction", "sliding_friction"});
  f.Number("value", &o->value, kRequired, Range::Of(core::limits::kFriction));
  f.String("note", &o->note, kRequired);
}

void ParseSegregation(const nlohmann::json& j, const std::string& path, const std::string& file,
                      WorkflowSegregation* s, JsonStatus* status) {
  JsonFields f(j, path, {"experiment_file", "replicates", "quick_replicates", "coated_wt_pct",
                         "excessive_gamma_J_m2", "size_scale", "stiffness_scale",
                         "funnel_orifice", "pair_overrides", "enabled"},
               status);
  f.Number("size_scale", &s->size_scale, kOptional, Range::Of(limits::kSizeScale));
  f.Number("stiffness_scale", &s->stiffness_scale, kOptional, Range::Of(limits::kStiffnessScale));
  if (status->ok() && (s->size_scale > 0) != (s->stiffness_scale > 0))
    f.Fail(s->size_scale > 0 ? "stiffness_scale" : "size_scale",
           "must be given together with " +
               std::string(s->size_scale > 0 ? "size_scale" : "stiffness_scale"));
  f.String("experiment_file", &s->experiment_file, kRequired);
  s->experiment_file = Resolve(file, s->experiment_file);
  int64_t n = s->replicates, q = s->quick_replicates;
  f.Integer("replicates", &n, kOptional, Range::Of(limits::kWorkflowReplicates));
  f.Integer("quick_replicates", &q, kOptional, Range::Of(limits::kWorkflowReplicates));
  s->replicates = static_cast<int>(n);
  s->quick_replicates = static_cast<int>(q);
  f.Number("coated_wt_pct", &s->coated_wt_pct, kOptional, Range::LeftOpen(0, 100));
  f.Number("excessive_gamma_J_m2", &s->excessive_gamma_J_m2, kOptional,
           Range::LeftOpen(0, 10, "J/m2"));
  f.Bool("enabled", &s->enabled, kOptional);
  if (const nlohmann::json* o = f.Object("funnel_orifice", kOptional); o && status->ok()) {
    // The same ranges as the experiment file's funnel (segregation_section.cc).
    JsonFields g(*o, path + ".funnel_orifice", {"effective_orifice_diameter_m", "beverloo_k", "note"},
                 status);
    g.Number("effective_orifice_diameter_m", &s->funnel_effective_orifice_diameter_m, kRequired,
             Range::Open(0, 10, "m"));
    g.Number("beverloo_k", &s->funnel_beverloo_k, kRequired, Range{0, 3, false, true, ""});
    g.String("note", &s->funnel_note, kRequired);
  }
  ForEach(f, "pair_overrides", kOptional, [&](const nlohmann::json& o, const std::string& p) {
    s->pair_overrides.emplace_back();
    ParsePairOverride(o, p, &s->pair_overrides.back(), status);
  });
}

void ParseFidelityCheck(const nlohmann::json& j, const std::string& path,
                        WorkflowFidelityCheck* c, JsonStatus* status) {
  JsonFields f(j, path, {"wt_pct", "size_scale", "stiffness_scale", "replicates", "enabled"},
               status);
  f.Number("wt_pct", &c->wt_pct, kOptional, Range::LeftOpen(0, 100));
  f.Number("size_scale", &c->size_scale, kOptional, Range::Of(limits::kSizeScale));
  f.Number("stiffness_scale", &c->stiffness_scale, kOptional, Range::Of(limits::kStiffnessScale));
  int64_t n = c->replicates;
  f.Integer("replicates", &n, kOptional, Range::Of(limits::kWorkflowReplicates));
  c->replicates = static_cast<int>(n);
  f.Bool("enabled", &c->enabled, kOptional);
}

void ParseReference(const nlohmann::json& j, const std::string& path, ReferenceValue* r,
                    JsonStatus* status) {
  JsonFields f(j, path, {"key", "quantity", "value", "uncertainty", "comparison", "unit", "source"},
               status);
  f.String("key", &r->key, kRequired, ReferenceKeys());
  f.String("quantity", &r->quantity, kRequired);
  f.Number("value", &r->value, kOptional);
  f.Number("uncertainty", &r->uncertainty, kOptional, Range::Closed(0, 1e30));
  f.String("comparison", &r->comparison, kOptional, {"equal", "at_least", "at_most"});
  f.String("unit", &r->unit, kRequired);
  f.String("source", &r->source, kRequired);
}

std::string Fingerprint(const std::string& text) {
  return std::to_string(std::hash<std::string>{}(text));
}

}  // namespace

bool LoadWorkflowFile(const std::string& path, WorkflowFile* out, std::string* error) {
  nlohmann::json doc;
  if (!ReadJsonFile(path, "workflow file", &doc, error)) return false;
  *out = WorkflowFile{};
  out->source = path;
  out->fingerprint = Fingerprint(doc.dump());
  JsonStatus status;
  JsonFields f(doc, "", {"format", "name", "description", "shape_assumption", "measurements",
                         "synthetic_measurements", "angle_uncertainty_deg",
                         "angle_uncertainty_note", "replicates", "species", "cohesion", "coating",
                         "segregation", "fidelity_check", "reference"}, &status);
  std::string format;
  f.String("format", &format, kRequired, {kWorkflowFormat});
  f.String("name", &out->name, kRequired);
  f.String("description", &out->description, kOptional);
  f.String("shape_assumption", &out->shape_assumption, kRequired);
  f.String("measurements", &out->measurements, kRequired);
  out->measurements = Resolve(path, out->measurements);
  f.String("synthetic_measurements", &out->synthetic_measurements, kOptional);
  out->synthetic_measurements = Resolve(path, out->synthetic_measurements);
  // From the floor that keeps χ² finite (limits::kMinUncertaintyFraction) to 20 deg: a repose
  // angle that scatters more is not a repeatable measurement.
  f.Number("angle_uncertainty_deg", &out->angle_uncertainty_deg, kRequired,
           Range::Closed(calibrate::FindObservable("angle_deg")->MinUncertainty(), 20, "deg"));
  f.String("angle_uncertainty_note", &out->angle_uncertainty_note, kRequired);
  int64_t replicates = out->replicates;
  f.Integer("replicates", &replicates, kOptional, Range::Of(limits::kWorkflowReplicates));
  out->replicates = static_cast<int>(replicates);
  ForEach(f, "species", kRequired, [&](const nlohmann::json& j, const std::string& p) {
    out->species.emplace_back();
    ParseSpecies(j, p, path, &out->species.back(), &status);
  });
  if (const nlohmann::json* c = f.Object("cohesion", kRequired); c && status.ok())
    ParseCohesion(*c, "cohesion", &out->cohesion, &status);
  if (const nlohmann::json* c = f.Object("coating", kRequired); c && status.ok())
    ParseCoating(*c, "coating", path, &out->coating, &status);
  if (const nlohmann::json* s = f.Object("segregation", kOptional); s && status.ok())
    ParseSegregation(*s, "segregation", path, &out->segregation, &status);
  else if (!s) out->segregation.enabled = false;
  if (const nlohmann::json* c = f.Object("fidelity_check", kOptional); c && status.ok())
    ParseFidelityCheck(*c, "fidelity_check", &out->fidelity_check, &status);
  else if (!c) out->fidelity_check.enabled = false;
  ForEach(f, "reference", kOptional, [&](const nlohmann::json& j, const std::string& p) {
    out->reference.emplace_back();
    ParseReference(j, p, &out->reference.back(), &status);
  });
  if (!status.ok()) return *error = path + ": " + status.message(), false;
  for (const std::string& p : {out->measurements, out->synthetic_measurements,
                               out->coating.experiment_file, out->segregation.experiment_file}) {
    if (!p.empty() && !fs::is_regular_file(p))
      return *error = path + ": file '" + p + "' not found", false;
  }
  for (const WorkflowSpecies& s : out->species)
    if (!fs::is_regular_file(s.experiment_file))
      return *error = path + ": file '" + s.experiment_file + "' not found", false;
  return true;
}

std::string ResolveWorkflowName(const std::string& name_or_path, const std::string& repo_root) {
  if (name_or_path.find('/') != std::string::npos || name_or_path.ends_with(".json"))
    return name_or_path;
  for (const fs::path& root : {fs::path("."), fs::path(repo_root)}) {
    fs::path p = root / "datasets" / name_or_path / "workflow.json";
    if (fs::is_regular_file(p)) return p.lexically_normal().string();
  }
  return name_or_path;
}

}  // namespace demcal::workflow
