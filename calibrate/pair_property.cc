#include "calibrate/pair_property.h"

namespace demcal::calibrate {
namespace {

struct PropertyInfo {
  PairProperty property;
  const char* key;
  const char* unit;
  double max;  // physical upper limit of the property
};

constexpr PropertyInfo kProperties[] = {
    {PairProperty::kSlidingFriction, "sliding_friction", "", 10},
    {PairProperty::kRollingFriction, "rolling_friction", "", 10},
    {PairProperty::kRestitution, "restitution", "", 1},
    {PairProperty::kInterfacialEnergy, "interfacial_energy_J_m2", "J/m2", 1e3},
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
    case PairProperty::kSlidingFriction: break;
  }
  return pair.sliding_friction;
}

}  // namespace

const char* PairPropertyKey(PairProperty property) { return Info(property).key; }
const char* PairPropertyUnit(PairProperty property) { return Info(property).unit; }
double PairPropertyMax(PairProperty property) { return Info(property).max; }

bool PairPropertyFromKey(const std::string& key, PairProperty* out) {
  for (const PropertyInfo& p : kProperties)
    if (key == p.key) return *out = p.property, true;
  return false;
}

void SetPairProperty(PairProperty property, int material_i, int material_j, double value,
                     core::Scene* model) {
  const size_t n = model->materials.size();
  Slot(model->pair_parameters[material_i * n + material_j], property) = value;
  Slot(model->pair_parameters[material_j * n + material_i], property) = value;
}

}  // namespace demcal::calibrate
