#include "calibrate/pair_property.h"

#include "core/bodies/clump_shapes.h"
#include "core/limits/physical_limits.h"

namespace demcal::calibrate {
namespace {

struct PropertyInfo {
  PairProperty property;
  const char* key;
  const char* unit;
  double min, max;  // physical limits of the property
  bool per_pair;    // a slot of the interaction table (false: a property of a species)
};

constexpr PropertyInfo kProperties[] = {
    {PairProperty::kSlidingFriction, "sliding_friction", "", 0, 10, true},
    {PairProperty::kRollingFriction, "rolling_friction", "", 0, 10, true},
    {PairProperty::kRestitution, "restitution", "", 0, 1, true},
    {PairProperty::kInterfacialEnergy, "interfacial_energy_J_m2", "J/m2", 0, 1e3, true},
    {PairProperty::kCohesionEnergyDensity, "cohesion_energy_density_J_m3", "J/m3", 0,
     core::limits::kCohesionEnergyDensity.hi, true},
    {PairProperty::kAspectRatio, "aspect_ratio", "", core::limits::kClumpAspectRatio.lo,
     core::limits::kClumpAspectRatio.hi, false},
};

const PropertyInfo& Info(PairProperty property) {
  for (const PropertyInfo& p : kProperties)
    if (p.property == property) return p;
  return kProperties[0];
}

double& Slot(core::PairParameters& pair, PairProperty property) {
  switch (property) {
    case PairProperty::kRollingFriction: return pair.rolling_friction;
    case PairProperty::kRestitution: return pair.restitution;
    case PairProperty::kInterfacialEnergy: return pair.interfacial_energy_J_m2;
    case PairProperty::kCohesionEnergyDensity: return pair.cohesion_energy_density_J_m3;
    case PairProperty::kSlidingFriction:
    case PairProperty::kAspectRatio: break;
  }
  return pair.sliding_friction;
}

// The same count of spheres re-chained on the prolate spheroid [aspect, 1, 1] (scale-free: the
// engine normalises a clump to the species' equivalent-volume diameter, core/materials).
void SetAspectRatio(int material, double aspect, core::Scene* model) {
  for (core::Species& s : model->species) {
    if (s.material != material || s.clump_shape.size() < 2) continue;
    core::ShapeApproximation shape;
    std::string ignored;  // only bounds IsValid accepts reach here
    if (!core::ApproximateEllipsoid({aspect, 1, 1}, static_cast<int>(s.clump_shape.size()), &shape,
                                    &ignored))
      continue;
    s.clump_shape.clear();
    for (const core::ClumpSphere& c : shape.spheres)
      s.clump_shape.push_back({c.centre_m, c.radius_m});
  }
}

}  // namespace

const char* PairPropertyKey(PairProperty property) { return Info(property).key; }
const char* PairPropertyUnit(PairProperty property) { return Info(property).unit; }
double PairPropertyMin(PairProperty property) { return Info(property).min; }
double PairPropertyMax(PairProperty property) { return Info(property).max; }

bool PairPropertyFromKey(const std::string& key, PairProperty* out) {
  for (const PropertyInfo& p : kProperties)
    if (key == p.key && p.per_pair) return *out = p.property, true;
  return false;
}

bool CalibratedPropertyFromKey(const std::string& key, PairProperty* out) {
  for (const PropertyInfo& p : kProperties)
    if (key == p.key) return *out = p.property, true;
  return false;
}

void SetPairProperty(PairProperty property, int material_i, int material_j, double value,
                     core::Scene* model) {
  if (property == PairProperty::kAspectRatio) return SetAspectRatio(material_i, value, model);
  const size_t n = model->materials.size();
  Slot(model->pair_parameters[material_i * n + material_j], property) = value;
  Slot(model->pair_parameters[material_j * n + material_i], property) = value;
}

}  // namespace demcal::calibrate
