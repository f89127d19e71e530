#include "files/scene_json.h"

#include <filesystem>
#include <sstream>

#include "files/json_document.h"
#include "files/json_fields.h"
#include "files/scene_json_sections.h"
#include "files/scene_limits.h"

namespace demcal::workflow {
namespace {

using nlohmann::json;

const std::vector<std::string>& TopLevelKeys() {
  static const std::vector<std::string> keys = {
      "format",    "description", "materials",    "species", "interactions",    "contact_model",
      "domain",    "periodic",    "gravity_m_s2", "walls",   "particles",       "fills",
      "factories", "sinks",       "seed",         "time",    "skin_m",          "max_wall_time_s",
      "output"};
  return keys;
}

void ParseDomain(JsonFields& top, core::Scene* scene, JsonStatus* status) {
  const json* domain = top.Object("domain", kRequired);
  if (!domain) return;
  JsonFields f(*domain, "domain", {"min_m", "max_m"}, status);
  f.Vector("min_m", &scene->domain_min_m, kRequired);
  f.Vector("max_m", &scene->domain_max_m, kRequired);
}

// periodic: {"x": bool, "y": bool, "z": bool}; a periodic axis wraps the domain box.
void ParsePeriodic(JsonFields& top, core::Scene* scene, JsonStatus* status) {
  const json* periodic = top.Object("periodic", kOptional);
  if (!periodic) return;
  JsonFields f(*periodic, "periodic", {"x", "y", "z"}, status);
  const char* axes[3] = {"x", "y", "z"};
  for (int a = 0; a < 3; ++a) {
    bool on = false;
    f.Bool(axes[a], &on, kOptional);
    scene->periodic[a] = on;
  }
}

void ParseTime(JsonFields& top, core::Scene* scene, JsonStatus* status) {
  const json* time = top.Object("time", kRequired);
  if (!time) return;
  JsonFields f(*time, "time", {"duration_s", "rayleigh_fraction", "timestep_s", "force_timestep"},
               status);
  core::TimeSettings& t = scene->time;
  f.Number("duration_s", &t.duration_s, kRequired);
  if (f.ok() && f.Has("rayleigh_fraction") && f.Has("timestep_s"))
    f.Fail("timestep_s", "cannot be given together with 'time.rayleigh_fraction'; give one");
  f.Number("rayleigh_fraction", &t.rayleigh_fraction, kOptional);
  // 0 means "derive from the Rayleigh time" inside the core; in a file that is "absent".
  f.Number("timestep_s", &t.timestep_s, kOptional, Range::LeftOpen(0, 1, "s"));
  f.Bool("force_timestep", &t.force_timestep, kOptional);
}

void ParseOutput(JsonFields& top, OutputSettings* output, JsonStatus* status) {
  const json* section = top.Object("output", kOptional);
  if (!section) return;
  JsonFields f(*section, "output",
               {"vtk_interval_s", "vtk_format", "mass_flow_interval_s", "mass_flow_planes"},
               status);
  f.Number("vtk_interval_s", &output->vtk_interval_s, kOptional, Range::LeftOpen(0, 1e6, "s"));
  std::string encoding = "binary";
  f.String("vtk_format", &encoding, kOptional, {"binary", "ascii"});
  if (f.ok()) core::io::ParseVtkEncoding(encoding, &output->vtk.encoding);
  f.Number("mass_flow_interval_s", &output->mass_flow_interval_s, kOptional,
           Range::LeftOpen(0, 1e6, "s"));
  const json* planes = f.Array("mass_flow_planes", kOptional);
  for (size_t i = 0; planes && i < planes->size() && status->ok(); ++i) {
    JsonFields p((*planes)[i], "output." + IndexPath("mass_flow_planes", i),
                 {"name", "point_m", "normal"}, status);
    core::SinkSpec plane;
    p.String("name", &plane.name, kRequired);
    p.Vector("point_m", &plane.point_m, kRequired);
    p.Vector("normal", &plane.normal, kRequired);
    const double length = core::Norm(plane.normal);
    if (p.ok() && !(length > 1e-12)) p.Fail("normal", "must be a non-zero vector");
    if (p.ok()) plane.normal = plane.normal / length;
    output->mass_flow_planes.push_back(plane);
  }
  if (status->ok() && !output->mass_flow_planes.empty() && !(output->mass_flow_interval_s > 0))
    f.Fail("mass_flow_planes", "needs 'output.mass_flow_interval_s' > 0 (the row interval)");
}

}  // namespace

bool ParseSceneJson(const json& document, const std::string& source, SceneFile* out,
                    std::string* error) {
  JsonStatus status;
  SceneFile file;
  file.source = source;
  core::Scene& scene = file.scene;
  JsonFields top(document, "", TopLevelKeys(), &status);
  std::string format;
  top.String("format", &format, kRequired);
  if (status.ok() && format != kSceneFormat)
    top.Fail("format", "= '" + format + "' is not supported; this demcal reads '" +
                           std::string(kSceneFormat) + "'");
  top.String("description", &file.description, kOptional);
  top.Unsigned("seed", &scene.seed, kRequired);
  internal::ParseMaterials(top, &scene, &status);
  internal::ParseSpecies(top, &scene, &status);
  internal::ParseInteractions(top, &scene, &status);
  internal::ParseContactModel(top, &scene, &status);
  ParseDomain(top, &scene, &status);
  ParsePeriodic(top, &scene, &status);
  top.Vector("gravity_m_s2", &scene.gravity_m_s2, kOptional);
  internal::ParseWalls(top, std::filesystem::path(source).parent_path().string(), &scene,
                       &status);
  internal::ParseParticles(top, &scene, &status);
  internal::ParseFills(top, &scene, &status);
  internal::ParseFactories(top, &scene, &status);
  internal::ParseSinks(top, &scene, &status);
  if (status.ok() && scene.particles.empty() && scene.fills.empty() && scene.factories.empty())
    status.Fail("the scene places no particles: give 'particles', 'fills' or 'factories'");
  ParseTime(top, &scene, &status);
  top.Number("skin_m", &scene.skin_m, kOptional, Range::LeftOpen(0, 1, "m"));
  top.Number("max_wall_time_s", &scene.max_wall_time_s, kOptional);
  ParseOutput(top, &file.output, &status);
  std::string core_error;
  if (status.ok() && !scene.IsValid(&core_error)) status.Fail(core_error);
  if (status.ok() && !CheckSceneLimits(file, &core_error)) status.Fail(core_error);
  if (!status.ok()) {
    if (error) *error = source + ": " + status.message();
    return false;
  }
  *out = std::move(file);
  return true;
}

bool ParseSceneText(const std::string& text, const std::string& source, SceneFile* out,
                    std::string* error) {
  json document;
  return ParseJsonText(text, source, &document, error) &&
         ParseSceneJson(document, source, out, error);
}

bool LoadSceneFile(const std::string& path, SceneFile* out, std::string* error) {
  json document;
  return ReadJsonFile(path, "scene file", &document, error) &&
         ParseSceneJson(document, path, out, error);
}

}  // namespace demcal::workflow
