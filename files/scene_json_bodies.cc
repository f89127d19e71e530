// Scene JSON sections: walls, particles, fills (see scene_json.h).
#include <cmath>
#include <algorithm>
#include <filesystem>
#include <map>

#include "files/scene_json_sections.h"
#include "core/limits/physical_limits.h"
#include "core/walls/walls.h"

namespace demcal::workflow::internal {
namespace {

using nlohmann::json;
namespace physical = core::limits;

// Fails unless max > min on every axis.
void CheckBoxOrder(JsonFields& f, const std::string& max_key, const core::Vec3& lo,
                   const core::Vec3& hi, const std::string& min_key) {
  if (!f.ok()) return;
  for (int a = 0; a < 3; ++a)
    if (!(hi[a] > lo[a]))
      return f.Fail(max_key, "must exceed '" + f.PathOf(min_key) + "' on every axis (axis " +
                                 "xyz"[a] + ": " + FormatNumber(lo[a]) +
                                 " >= " + FormatNumber(hi[a]) + ")");
}

// Reads a required non-zero direction and normalises it.
void ReadAxis(JsonFields& f, const std::string& key, core::Vec3* out, const std::string& what) {
  f.Vector(key, out, kRequired);
  if (!f.ok()) return;
  const double length = core::Norm(*out);
  if (!(length > 1e-12))
    return f.Fail(key, "must be a non-zero vector (" + what + "; normalised to unit length)");
  *out = *out / length;
}

// The keys every wall type accepts: prescribed translation and the torque reference point.
void ReadMotion(JsonFields& f, core::Wall* w) {
  f.Vector("velocity_m_s", &w->velocity_m_s, kOptional);
  f.Number("motion_start_s", &w->motion_start_s, kOptional, Range::Closed(0, 1e9, "s"));
  f.Number("motion_end_s", &w->motion_end_s, kOptional, Range::Closed(0, 1e9, "s"));
  f.Vector("load_point_m", &w->load_point_m, kOptional);
  f.Number("remove_at_s", &w->remove_at_s, kOptional, Range::Closed(0, 1e9, "s"));
  if (f.ok() && !(w->motion_end_s >= w->motion_start_s))
    f.Fail("motion_end_s", "must not be before '" + f.PathOf("motion_start_s") + "' (" +
                               FormatNumber(w->motion_end_s) + " < " +
                               FormatNumber(w->motion_start_s) + ")");
}

void ParsePlane(JsonFields& f, core::Wall w, core::Scene* scene) {
  core::PlaneSurface plane;
  f.Vector("point_m", &plane.point_m, kRequired);
  ReadAxis(f, "normal", &plane.normal, "it points into the particle region");
  if (!f.ok()) return;
  w.shape = plane;
  scene->walls.push_back(w);
}

void ParseBox(JsonFields& f, const core::Wall& common, core::Scene* scene) {
  core::Vec3 lo, hi;
  bool open_top = false;
  f.Vector("min_m", &lo, kRequired);
  f.Vector("max_m", &hi, kRequired);
  f.Bool("open_top", &open_top, kOptional);
  CheckBoxOrder(f, "max_m", lo, hi, "min_m");
  if (!f.ok()) return;
  for (const core::PlaneWall& face :
       core::BoxInnerFaces(common.name, lo, hi, common.material, open_top)) {
    core::Wall w = common;
    w.name = face.name;
    w.shape = core::PlaneSurface{face.point_m, face.normal};
    scene->walls.push_back(w);
  }
}

void ParseCylinder(JsonFields& f, core::Wall w, core::Scene* scene) {
  core::CylinderSurface c;
  f.Vector("axis_point_m", &c.axis_point_m, kRequired);
  ReadAxis(f, "axis", &c.axis, "the cylinder's axis direction");
  f.Number("radius_m", &c.radius_m, kRequired, Range::LeftOpen(0, physical::kWallRadius.hi, "m"));
  f.Number("axial_min_m", &c.axial_min_m, kOptional);
  f.Number("axial_max_m", &c.axial_max_m, kOptional);
  f.Bool("inside", &c.inside, kOptional);
  f.Bool("shell", &w.shell, kOptional);
  if (f.ok() && !(c.axial_max_m > c.axial_min_m))
    return f.Fail("axial_max_m", "must exceed '" + f.PathOf("axial_min_m") + "' (" +
                                     FormatNumber(c.axial_min_m) +
                                     " >= " + FormatNumber(c.axial_max_m) + ")");
  if (!f.ok()) return;
  w.shape = c;
  scene->walls.push_back(w);
}

void ParseCone(JsonFields& f, core::Wall w, core::Scene* scene) {
  core::ConeFrustumSurface c;
  f.Vector("axis_point_m", &c.axis_point_m, kRequired);
  ReadAxis(f, "axis", &c.axis, "the cone's axis direction");
  f.Number("height0_m", &c.height0_m, kRequired);
  f.Number("radius0_m", &c.radius0_m, kRequired, Range::Of(physical::kWallRadius, "m"));
  f.Number("height1_m", &c.height1_m, kRequired);
  f.Number("radius1_m", &c.radius1_m, kRequired, Range::Of(physical::kWallRadius, "m"));
  f.Bool("inside", &c.inside, kOptional);
  f.Bool("shell", &w.shell, kOptional);
  if (f.ok() && c.height1_m == c.height0_m)
    return f.Fail("height1_m", "must differ from '" + f.PathOf("height0_m") + "' (both " +
                                   FormatNumber(c.height0_m) + ")");
  if (f.ok() && c.radius0_m == 0 && c.radius1_m == 0)
    return f.Fail("radius1_m", "must be > 0 when '" + f.PathOf("radius0_m") + "' is 0");
  if (!f.ok()) return;
  w.shape = c;
  scene->walls.push_back(w);
}

// `file` is relative to the scene file's directory `base_dir` unless absolute.
void ParseMesh(JsonFields& f, core::Wall w, const std::string& base_dir, core::Scene* scene) {
  std::string file;
  core::MeshWallOptions options;
  core::Vec3 offset;
  f.String("file", &file, kRequired);
  f.Number("scale", &options.stl.scale, kOptional, Range::LeftOpen(0, 1e6));
  f.Vector("offset_m", &offset, kOptional);
  if (!f.ok()) return;
  std::filesystem::path path(file);
  if (path.is_relative() && !base_dir.empty()) path = std::filesystem::path(base_dir) / path;
  std::string error;
  if (!core::ReadMeshWall(path.string(), options, &w, &error)) return f.Fail("file", error);
  std::get<core::MeshRef>(w.shape).offset_m = offset;
  scene->walls.push_back(w);
}

// particles[i].orientation: a quaternion [w, x, y, z] (body principal frame -> space),
// normalised; only for clump species.
void ReadOrientation(JsonFields& f, const core::Scene& scene, core::ParticleSpec* p) {
  std::vector<double> q;
  f.Numbers("orientation", 4, &q, kOptional);
  if (!f.ok() || q.empty()) return;
  if (scene.species[p->species].clump_shape.empty())
    return f.Fail("orientation", "applies only to clump species ('" +
                                     scene.species[p->species].name + "' is a plain sphere)");
  const double norm = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  if (!(norm > 1e-12))
    return f.Fail("orientation", "must be a non-zero quaternion [w, x, y, z] (it is normalised)");
  p->orientation = core::Quaternion(q[0] / norm, q[1] / norm, q[2] / norm, q[3] / norm);
}

}  // namespace

void ParseWalls(JsonFields& top, const std::string& base_dir, core::Scene* scene,
                JsonStatus* status) {
  const json* list = top.Array("walls", kOptional);
  if (!list) return;
  const std::vector<std::string> common = {"type",           "name",         "material",
                                           "velocity_m_s",   "motion_start_s", "motion_end_s",
                                           "load_point_m",   "remove_at_s"};
  const std::map<std::string, std::vector<std::string>> specific = {
      {"plane", {"point_m", "normal"}},
      {"box", {"min_m", "max_m", "open_top"}},
      {"cylinder",
       {"axis_point_m", "axis", "radius_m", "axial_min_m", "axial_max_m", "inside", "shell"}},
      {"cone",
       {"axis_point_m", "axis", "height0_m", "radius0_m", "height1_m", "radius1_m", "inside",
        "shell"}},
      {"mesh", {"file", "scale", "offset_m"}}};
  std::vector<std::string> types, all_keys = common;
  for (const auto& [type, keys] : specific) {
    types.push_back(type);
    for (const std::string& k : keys)
      if (std::find(all_keys.begin(), all_keys.end(), k) == all_keys.end()) all_keys.push_back(k);
  }
  const std::vector<std::string> materials = MaterialNames(*scene);
  for (size_t i = 0; i < list->size() && status->ok(); ++i) {
    const std::string path = IndexPath("walls", i);
    std::string type;
    {
      JsonFields probe((*list)[i], path, all_keys, status);
      probe.String("type", &type, kRequired, {"plane", "box", "cylinder", "cone", "mesh"});
    }
    if (!status->ok()) return;
    std::vector<std::string> keys = common;
    keys.insert(keys.end(), specific.at(type).begin(), specific.at(type).end());
    JsonFields f((*list)[i], path, keys, status);
    core::Wall w;
    w.name = path;
    f.String("name", &w.name, kOptional);
    w.material = ReadNameReference(f, "material", "material", materials, status);
    ReadMotion(f, &w);
    if (!f.ok()) return;
    if (type == "plane")
      ParsePlane(f, w, scene);
    else if (type == "box")
      ParseBox(f, w, scene);
    else if (type == "cylinder")
      ParseCylinder(f, w, scene);
    else if (type == "cone")
      ParseCone(f, w, scene);
    else
      ParseMesh(f, w, base_dir, scene);
  }
}

void ParseParticles(JsonFields& top, core::Scene* scene, JsonStatus* status) {
  const json* list = top.Array("particles", kOptional);
  if (!list) return;
  const std::vector<std::string> species = SpeciesNames(*scene);
  for (size_t i = 0; i < list->size() && status->ok(); ++i) {
    JsonFields f((*list)[i], IndexPath("particles", i),
                 {"species", "position_m", "velocity_m_s", "angular_velocity_rad_s", "diameter_m",
                  "orientation", "fixed"},
                 status);
    core::ParticleSpec p;
    p.species = ReadNameReference(f, "species", "species", species, status);
    f.Vector("position_m", &p.position_m, kRequired);
    f.Vector("velocity_m_s", &p.velocity_m_s, kOptional);
    f.Vector("angular_velocity_rad_s", &p.angular_velocity_rad_s, kOptional);
    // Absent: drawn from the species' size distribution (core's diameter_m = 0).
    f.Number("diameter_m", &p.diameter_m, kOptional, Range::Of(physical::kDiameter, "m"));
    ReadOrientation(f, *scene, &p);
    f.Bool("fixed", &p.fixed, kOptional);  // glued in place (a frozen base); spheres only
    scene->particles.push_back(p);
  }
}

void ParseFills(JsonFields& top, core::Scene* scene, JsonStatus* status) {
  const json* list = top.Array("fills", kOptional);
  if (!list) return;
  const std::vector<std::string> species = SpeciesNames(*scene);
  for (size_t i = 0; i < list->size() && status->ok(); ++i) {
    JsonFields f((*list)[i], IndexPath("fills", i), {"species", "region", "count", "velocity_m_s"},
                 status);
    core::FillSpec fill;
    fill.species = ReadNameReference(f, "species", "species", species, status);
    ParseInsertionRegion(f, &fill.region, status);
    f.Integer("count", &fill.count, kRequired);
    f.Vector("velocity_m_s", &fill.velocity_m_s, kOptional);
    scene->fills.push_back(fill);
  }
}

}  // namespace demcal::workflow::internal
