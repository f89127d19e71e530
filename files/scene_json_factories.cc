// Scene JSON section: factories (see scene_json.h), rate-controlled insertion during the run.
#include <cmath>

#include "files/scene_json_sections.h"
#include "core/insertion/factory.h"
#include "core/limits/physical_limits.h"

namespace demcal::workflow::internal {

using nlohmann::json;

void ParseInsertionRegion(JsonFields& f, core::InsertionRegion* region, JsonStatus* status) {
  const json* r = f.Object("region", kRequired);
  if (!r) return;
  std::string shape = "box";
  {
    JsonFields probe(*r, f.PathOf("region"),
                     {"shape", "min_m", "max_m", "axis_point_m", "radius_m", "z_range_m"}, status);
    probe.String("shape", &shape, kOptional, {"box", "cylinder"});
  }
  if (!status->ok()) return;
  if (shape == "box") {
    JsonFields b(*r, f.PathOf("region"), {"shape", "min_m", "max_m"}, status);
    core::Vec3 lo, hi;
    b.Vector("min_m", &lo, kRequired);
    b.Vector("max_m", &hi, kRequired);
    *region = core::InsertionRegion::Box(lo, hi);
    return;
  }
  JsonFields c(*r, f.PathOf("region"), {"shape", "axis_point_m", "radius_m", "z_range_m"}, status);
  core::Vec3 axis_point;
  double radius = 0;
  std::vector<double> z;
  c.Vector("axis_point_m", &axis_point, kRequired);
  c.Number("radius_m", &radius, kRequired, Range::LeftOpen(0, core::limits::kCoordinate.hi, "m"));
  c.Numbers("z_range_m", 2, &z, kRequired);
  if (c.ok() && !(z[1] > z[0])) c.Fail("z_range_m", "must be [z_min, z_max] with z_max > z_min");
  if (c.ok()) *region = core::InsertionRegion::Cylinder(axis_point, radius, z[0], z[1]);
}

void ParseFactories(JsonFields& top, core::Scene* scene, JsonStatus* status) {
  const json* list = top.Array("factories", kOptional);
  if (!list) return;
  const std::vector<std::string> species = SpeciesNames(*scene);
  for (size_t i = 0; i < list->size() && status->ok(); ++i) {
    JsonFields f((*list)[i], IndexPath("factories", i),
                 {"name", "species", "region", "mass_rate_kg_s", "start_s", "end_s",
                  "total_mass_kg", "velocity_m_s", "batch_interval_s", "region_velocity_m_s",
                  "follow_heap"},
                 status);
    core::FactorySpec spec;
    spec.name = f.path();
    f.String("name", &spec.name, kOptional);
    if (const json* mix = f.Array("species", kRequired)) {
      if (mix->empty()) f.Fail("species", "must list at least one species");
      for (size_t k = 0; k < mix->size() && status->ok(); ++k) {
        JsonFields m((*mix)[k], IndexPath(f.PathOf("species"), k), {"name", "mass_fraction"},
                     status);
        const int index = ReadNameReference(m, "name", "species", species, status);
        double fraction = 1;  // a single species needs no fraction
        m.Number("mass_fraction", &fraction, mix->size() == 1 ? kOptional : kRequired);
        spec.species.push_back(index);
        spec.mass_fractions.push_back(fraction);
      }
    }
    ParseInsertionRegion(f, &spec.region, status);
    f.Number("mass_rate_kg_s", &spec.mass_rate_kg_s, kRequired);  // Scene::IsValid: kMassRate
    f.Number("start_s", &spec.start_s, kOptional);
    f.Number("end_s", &spec.end_s, kOptional);
    f.Number("total_mass_kg", &spec.total_mass_kg, kOptional);
    f.Vector("velocity_m_s", &spec.velocity_m_s, kOptional);
    f.Number("batch_interval_s", &spec.batch_interval_s, kOptional);
    f.Vector("region_velocity_m_s", &spec.region_velocity_m_s, kOptional);
    if (const json* follow = f.Object("follow_heap", kOptional)) {
      JsonFields h(*follow, f.PathOf("follow_heap"), {"clearance_m", "settled_speed_m_s"}, status);
      h.Number("clearance_m", &spec.follow_heap_clearance_m, kRequired,
               Range::Open(0, 1e3, "m"));
      h.Number("settled_speed_m_s", &spec.settled_speed_m_s, kOptional,
               Range::Open(0, 1e3, "m/s"));
    }
    scene->factories.push_back(spec);
  }
}

}  // namespace demcal::workflow::internal
