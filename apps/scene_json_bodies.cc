// Scene JSON sections: walls, particles, fills (see scene_json.h).
#include <cmath>

#include "apps/scene_json_sections.h"
#include "core/walls.h"

namespace demcal::apps::internal {
namespace {

using nlohmann::json;

// Fails unless max > min on every axis.
void CheckBoxOrder(JsonFields& f, const std::string& max_key, const core::Vec3& lo,
                   const core::Vec3& hi, const std::string& min_key) {
  if (!f.ok()) return;
  for (int a = 0; a < 3; ++a)
    if (!(hi[a] > lo[a]))
      return f.Fail(max_key, "must exceed '" + f.PathOf(min_key) + "' on every axis (axis " +
                                 "xyz"[a] + ": " + std::to_string(lo[a]) +
                                 " >= " + std::to_string(hi[a]) + ")");
}

void ParsePlane(JsonFields& f, const std::string& name, int material, core::Scene* scene) {
  core::PlaneWall w;
  w.name = name;
  w.material = material;
  f.Vector("point_m", &w.point_m, kRequired);
  f.Vector("normal", &w.normal, kRequired);
  f.Vector("velocity_m_s", &w.velocity_m_s, kOptional);
  if (!f.ok()) return;
  const double length = core::Norm(w.normal);
  if (!(length > 1e-12))
    return f.Fail("normal",
                  "must be a non-zero vector (it points into the particle region and "
                  "is normalised to unit length)");
  w.normal = w.normal / length;
  scene->walls.push_back(w);
}

void ParseBox(JsonFields& f, const std::string& name, int material, core::Scene* scene) {
  core::Vec3 lo, hi;
  bool open_top = false;
  f.Vector("min_m", &lo, kRequired);
  f.Vector("max_m", &hi, kRequired);
  f.Bool("open_top", &open_top, kOptional);
  CheckBoxOrder(f, "max_m", lo, hi, "min_m");
  if (!f.ok()) return;
  for (const core::PlaneWall& w : core::BoxInnerFaces(name, lo, hi, material, open_top))
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

void ParseWalls(JsonFields& top, core::Scene* scene, JsonStatus* status) {
  const json* list = top.Array("walls", kOptional);
  if (!list) return;
  const std::vector<std::string> plane_keys = {"type",    "name",   "material",
                                               "point_m", "normal", "velocity_m_s"};
  const std::vector<std::string> box_keys = {"type",  "name",  "material",
                                             "min_m", "max_m", "open_top"};
  const std::vector<std::string> all_keys = {"type",    "name",   "material",
                                             "point_m", "normal", "velocity_m_s",
                                             "min_m",   "max_m",  "open_top"};
  const std::vector<std::string> materials = MaterialNames(*scene);
  for (size_t i = 0; i < list->size() && status->ok(); ++i) {
    const std::string path = IndexPath("walls", i);
    std::string type;
    {
      JsonFields probe((*list)[i], path, all_keys, status);
      probe.String("type", &type, kRequired, {"plane", "box"});
    }
    if (!status->ok()) return;
    JsonFields f((*list)[i], path, type == "plane" ? plane_keys : box_keys, status);
    std::string name = path;
    f.String("name", &name, kOptional);
    const int material = ReadNameReference(f, "material", "material", materials, status);
    if (!f.ok()) return;
    if (type == "plane")
      ParsePlane(f, name, material, scene);
    else
      ParseBox(f, name, material, scene);
  }
}

void ParseParticles(JsonFields& top, core::Scene* scene, JsonStatus* status) {
  const json* list = top.Array("particles", kOptional);
  if (!list) return;
  const std::vector<std::string> species = SpeciesNames(*scene);
  for (size_t i = 0; i < list->size() && status->ok(); ++i) {
    JsonFields f((*list)[i], IndexPath("particles", i),
                 {"species", "position_m", "velocity_m_s", "angular_velocity_rad_s", "diameter_m",
                  "orientation"},
                 status);
    core::ParticleSpec p;
    p.species = ReadNameReference(f, "species", "species", species, status);
    f.Vector("position_m", &p.position_m, kRequired);
    f.Vector("velocity_m_s", &p.velocity_m_s, kOptional);
    f.Vector("angular_velocity_rad_s", &p.angular_velocity_rad_s, kOptional);
    // Absent: drawn from the species' size distribution (core's diameter_m = 0).
    f.Number("diameter_m", &p.diameter_m, kOptional, Range::LeftOpen(0, 10, "m"));
    ReadOrientation(f, *scene, &p);
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
    if (const json* region = f.Object("region", kRequired)) {
      JsonFields r(*region, f.PathOf("region"), {"min_m", "max_m"}, status);
      r.Vector("min_m", &fill.region_min_m, kRequired);
      r.Vector("max_m", &fill.region_max_m, kRequired);
    }
    f.Integer("count", &fill.count, kRequired);
    f.Vector("velocity_m_s", &fill.velocity_m_s, kOptional);
    scene->fills.push_back(fill);
  }
}

}  // namespace demcal::apps::internal
