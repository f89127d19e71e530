// Scene JSON sections: materials, species, interactions, contact_model (see scene_json.h).
#include <algorithm>

#include "files/scene_json_sections.h"
#include "core/bodies/clump_shapes.h"
#include "core/contact/rolling_model.h"
#include "objectives/common/input_limits.h"

namespace demcal::workflow::internal {

namespace limits = objectives::limits;
namespace physical = core::limits;
namespace {

using core::PairParameters;
using nlohmann::json;

// Fails if `name` was already used by an earlier entry of the same list.
void CheckUnique(JsonFields& f, const std::vector<std::string>& earlier, const std::string& name) {
  if (std::find(earlier.begin(), earlier.end(), name) != earlier.end())
    f.Fail("name", "= '" + name + "' is used twice; names must be unique");
}

// The interaction keys that a default or a pair entry may set (JSON ranges; the core checks
// the resolved table again).
void ReadPairFields(JsonFields& f, PairParameters* p) {
  f.Number("sliding_friction", &p->sliding_friction, kOptional, Range::Of(physical::kFriction));
  f.Number("rolling_friction", &p->rolling_friction, kOptional, Range::Of(physical::kFriction));
  f.Number("restitution", &p->restitution, kOptional, Range::Of(physical::kRestitution));
  f.Number("interfacial_energy_J_m2", &p->interfacial_energy_J_m2, kOptional,
           Range::Of(physical::kInterfacialEnergy, "J/m2"));
  f.Number("cohesion_energy_density_J_m3", &p->cohesion_energy_density_J_m3, kOptional,
           Range::Of(physical::kCohesionEnergyDensity, "J/m3"));
}

const std::vector<std::string>& PairKeys() {
  static const std::vector<std::string> keys = {"sliding_friction", "rolling_friction",
                                                "restitution", "interfacial_energy_J_m2",
                                                "cohesion_energy_density_J_m3"};
  return keys;
}

// species[i].clump: {"spheres": [{"centre": [x, y, z], "radius": r}, ...]} or
// {"ellipsoid": {"semi_axes": [a, b, c], "sphere_count": n}}. Lengths are in any one unit: the
// engine scales the shape so that the species' diameter is its equivalent-volume diameter.
void ParseClump(JsonFields& f, core::Species* sp, JsonStatus* status) {
  const json* clump = f.Object("clump", kOptional);
  if (!clump) return;
  JsonFields c(*clump, f.PathOf("clump"), {"spheres", "ellipsoid"}, status);
  if (c.ok() && c.Has("spheres") == c.Has("ellipsoid"))
    c.Fail("spheres", "give exactly one of 'spheres' or 'ellipsoid'");
  if (const json* spheres = c.Array("spheres", kOptional)) {
    if (spheres->empty()) c.Fail("spheres", "must list at least one sphere");
    for (size_t k = 0; k < spheres->size() && status->ok(); ++k) {
      JsonFields s((*spheres)[k], IndexPath(c.PathOf("spheres"), k), {"centre", "radius"}, status);
      core::ShapeSphere member;
      s.Vector("centre", &member.centre, kRequired);
      s.Number("radius", &member.radius, kRequired, Range::Of(physical::kClumpLength));
      sp->clump_shape.push_back(member);
    }
  }
  if (const json* ellipsoid = c.Object("ellipsoid", kOptional)) {
    JsonFields e(*ellipsoid, c.PathOf("ellipsoid"), {"semi_axes", "sphere_count"}, status);
    core::Vec3 axes;
    int64_t n = 0;
    e.Vector("semi_axes", &axes, kRequired);
    e.Integer("sphere_count", &n, kRequired, Range::Of(limits::kClumpSpheres));
    if (!e.ok()) return;
    std::string why;
    if (!core::CheckEllipsoidSemiAxes(axes, &why)) return e.Fail("semi_axes", why);
    core::ShapeApproximation shape;
    if (!core::ApproximateEllipsoid(axes, static_cast<int>(n), &shape, &why))
      return e.Fail("semi_axes", "cannot be approximated: " + why);
    for (const core::ClumpSphere& s : shape.spheres)
      sp->clump_shape.push_back({s.centre_m, s.radius_m});
  }
}

}  // namespace

std::vector<std::string> MaterialNames(const core::Scene& scene) {
  std::vector<std::string> names;
  for (const core::Material& m : scene.materials) names.push_back(m.name);
  return names;
}

std::vector<std::string> SpeciesNames(const core::Scene& scene) {
  std::vector<std::string> names;
  for (const core::Species& s : scene.species) names.push_back(s.name);
  return names;
}

int ResolveName(const json& value, const std::string& path, const std::string& what,
                const std::vector<std::string>& names, JsonStatus* status) {
  if (!status->ok()) return -1;
  if (!value.is_string()) {
    status->Fail("field '" + path + "' must be the name of a " + what + " (a string), got " +
                 JsonTypeName(value) + " " + value.dump());
    return -1;
  }
  const std::string& name = value.get_ref<const std::string&>();
  const auto it = std::find(names.begin(), names.end(), name);
  if (it != names.end()) return static_cast<int>(it - names.begin());
  std::string defined;
  for (const std::string& n : names) defined += (defined.empty() ? "" : ", ") + n;
  status->Fail("field '" + path + "' = '" + name + "' names no " + what +
               " (defined: " + (defined.empty() ? "none" : defined) + ")");
  return -1;
}

int ReadNameReference(JsonFields& f, const std::string& key, const std::string& what,
                      const std::vector<std::string>& names, JsonStatus* status) {
  const json* value = f.Value(key, kRequired);
  return value ? ResolveName(*value, f.PathOf(key), what, names, status) : -1;
}

void ParseMaterials(JsonFields& top, core::Scene* scene, JsonStatus* status) {
  const json* list = top.Array("materials", kRequired);
  if (!list) return;
  if (list->empty()) top.Fail("materials", "must list at least one material");
  for (size_t i = 0; i < list->size() && status->ok(); ++i) {
    JsonFields f(
        (*list)[i], IndexPath("materials", i),
        {"name", "youngs_modulus_Pa", "shear_modulus_Pa", "poisson_ratio", "density_kg_m3"},
        status);
    core::Material m;
    f.String("name", &m.name, kRequired);
    if (f.ok()) CheckUnique(f, MaterialNames(*scene), m.name);
    f.Number("poisson_ratio", &m.poisson_ratio, kRequired, Range::Of(physical::kPoissonRatio));
    const bool has_e = f.Has("youngs_modulus_Pa"), has_g = f.Has("shear_modulus_Pa");
    if (f.ok() && has_e == has_g)
      f.Fail(has_e ? "shear_modulus_Pa" : "youngs_modulus_Pa",
             has_e ? "cannot be given together with 'youngs_modulus_Pa'; give exactly one"
                   : "is missing: give exactly one of youngs_modulus_Pa, shear_modulus_Pa");
    const Range modulus = Range::Of(physical::kYoungsModulus, "Pa");
    if (has_e) f.Number("youngs_modulus_Pa", &m.youngs_modulus_Pa, kRequired, modulus);
    if (has_g) {
      double g = 0;
      f.Number("shear_modulus_Pa", &g, kRequired, modulus);
      m.youngs_modulus_Pa = core::Material::YoungsFromShear(g, m.poisson_ratio);
    }
    m.density_kg_m3 = 0;  // only particle materials need one; checked in ParseSpecies
    f.Number("density_kg_m3", &m.density_kg_m3, kOptional);
    scene->materials.push_back(m);
  }
}

void ParseSpecies(JsonFields& top, core::Scene* scene, JsonStatus* status) {
  const json* list = top.Array("species", kRequired);
  if (!list) return;
  if (list->empty()) top.Fail("species", "must list at least one species");
  const std::vector<std::string> materials = MaterialNames(*scene);
  for (size_t i = 0; i < list->size() && status->ok(); ++i) {
    JsonFields f((*list)[i], IndexPath("species", i),
                 {"name", "material", "diameter_m", "diameter_range_m", "diameter_table", "clump"},
                 status);
    core::Species sp;
    f.String("name", &sp.name, kRequired);
    if (f.ok()) CheckUnique(f, SpeciesNames(*scene), sp.name);
    sp.material = ReadNameReference(f, "material", "material", materials, status);
    if (f.ok() && !(scene->materials[sp.material].density_kg_m3 > 0)) {
      status->Fail("field 'materials[" + std::to_string(sp.material) +
                   "].density_kg_m3' is required (> 0) because species '" + sp.name +
                   "' is made of material '" + materials[sp.material] + "'");
    }
    const int given = f.Has("diameter_m") + f.Has("diameter_range_m") + f.Has("diameter_table");
    if (f.ok() && given != 1)
      f.Fail("diameter_m", given == 0 ? "is missing: give exactly one of diameter_m, "
                                        "diameter_range_m, diameter_table"
                                      : "conflicts: give exactly one of diameter_m, "
                                        "diameter_range_m, diameter_table");
    using Kind = core::SizeDistribution::Kind;
    if (f.Has("diameter_m")) {
      sp.size.kind = Kind::kFixed;
      f.Number("diameter_m", &sp.size.diameter_m, kRequired, Range::Of(physical::kDiameter, "m"));
    } else if (f.Has("diameter_range_m")) {
      std::vector<double> range;
      f.Numbers("diameter_range_m", 2, &range, kRequired);
      if (f.ok() && !(range[0] > 0 && range[0] <= range[1] && range[1] <= 10))
        f.Fail("diameter_range_m", "= [" + std::to_string(range[0]) + ", " +
                                       std::to_string(range[1]) +
                                       "] must satisfy 0 < min <= max <= 10 m");
      if (f.ok()) {
        sp.size.kind = Kind::kUniform;
        sp.size.min_diameter_m = range[0];
        sp.size.max_diameter_m = range[1];
      }
    } else if (const json* table = f.Array("diameter_table", kRequired)) {
      sp.size.kind = Kind::kTable;
      if (table->empty()) f.Fail("diameter_table", "must have at least one row");
      for (size_t k = 0; k < table->size() && status->ok(); ++k) {
        JsonFields row((*table)[k], IndexPath(f.PathOf("diameter_table"), k),
                       {"diameter_m", "number_fraction"}, status);
        double d = 0, fraction = 0;
        row.Number("diameter_m", &d, kRequired);
        row.Number("number_fraction", &fraction, kRequired);
        sp.size.table_diameter_m.push_back(d);
        sp.size.table_number_fraction.push_back(fraction);
      }
    }
    ParseClump(f, &sp, status);
    scene->species.push_back(sp);
  }
}

void ParseInteractions(JsonFields& top, core::Scene* scene, JsonStatus* status) {
  const size_t n = scene->materials.size();
  PairParameters defaults;
  static const json kEmpty = json::object();
  const json* section = top.Object("interactions", kOptional);
  JsonFields f(section ? *section : kEmpty, "interactions", {"default", "pairs"}, status);
  if (const json* d = f.Object("default", kOptional)) {
    JsonFields df(*d, f.PathOf("default"), PairKeys(), status);
    ReadPairFields(df, &defaults);
  }
  scene->pair_parameters.assign(n * n, defaults);
  const json* pairs = f.Array("pairs", kOptional);
  if (!pairs || !status->ok()) return;
  const std::vector<std::string> names = MaterialNames(*scene);
  std::vector<bool> seen(n * n, false);
  for (size_t k = 0; k < pairs->size() && status->ok(); ++k) {
    std::vector<std::string> keys = PairKeys();
    keys.insert(keys.begin(), "materials");
    JsonFields pf((*pairs)[k], IndexPath(f.PathOf("pairs"), k), keys, status);
    const json* two = pf.Array("materials", kRequired);
    if (two && two->size() != 2)
      pf.Fail("materials", "must name exactly two materials, e.g. [\"glass\", \"steel\"]");
    if (!pf.ok()) return;
    int index[2];
    for (int side = 0; side < 2; ++side)
      index[side] = ResolveName((*two)[side], IndexPath(pf.PathOf("materials"), side), "material",
                                names, status);
    if (!status->ok()) return;
    const size_t ij = index[0] * n + index[1], ji = index[1] * n + index[0];
    if (seen[ij])
      pf.Fail("materials", "repeats the pair (" + names[index[0]] + ", " + names[index[1]] +
                               "); each pair may appear once");
    PairParameters p = defaults;
    ReadPairFields(pf, &p);
    seen[ij] = seen[ji] = true;
    scene->pair_parameters[ij] = scene->pair_parameters[ji] = p;
  }
}

void ParseContactModel(JsonFields& top, core::Scene* scene, JsonStatus* status) {
  const json* section = top.Object("contact_model", kOptional);
  if (!section) return;
  JsonFields f(*section, "contact_model", {"rolling", "epsd_damping_ratio", "jkr_rolling_load"},
               status);
  f.String("rolling", &scene->rolling.name, kOptional, core::RollingModelNames());
  f.String("jkr_rolling_load", &scene->rolling.jkr_rolling_load, kOptional,
           core::JkrRollingLoadNames());
  f.Number("epsd_damping_ratio", &scene->rolling.epsd_damping_ratio, kOptional,
           Range::Of(physical::kDampingRatio));
  if (f.ok() && f.Has("epsd_damping_ratio") && scene->rolling.name != "epsd")
    f.Fail("epsd_damping_ratio",
           "applies only to rolling = \"epsd\" (rolling is \"" + scene->rolling.name + "\")");
}

}  // namespace demcal::workflow::internal
