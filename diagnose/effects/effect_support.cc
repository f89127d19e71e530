#include "diagnose/effects/effect_support.h"

namespace demcal::diagnose {
namespace {

double Get(calibrate::PairProperty property, const core::PairParameters& p) {
  switch (property) {
    case calibrate::PairProperty::kSlidingFriction: return p.sliding_friction;
    case calibrate::PairProperty::kRollingFriction: return p.rolling_friction;
    case calibrate::PairProperty::kRestitution: return p.restitution;
    case calibrate::PairProperty::kInterfacialEnergy: return p.interfacial_energy_J_m2;
    case calibrate::PairProperty::kAspectRatio: break;  // a species' shape: no effect shifts it
  }
  return 0;
}

}  // namespace

bool FindMaterial(const core::Scene& model, const std::string& name, int* material, std::string* why) {
  *material = model.MaterialIndex(name);
  if (*material >= 0) return true;
  *why = "the model has no material '" + name + "'";
  return false;
}

bool FindSpecies(const core::Scene& model, const EffectContext& context, int* species, std::string* why) {
  *species = model.SpeciesIndex(context.species);
  if (*species >= 0) return true;
  *why = "the model has no species '" + context.species + "'";
  return false;
}

bool ShiftPairProperty(calibrate::PairProperty property, int i, int j, double delta, core::Scene* model,
                       std::string* why) {
  const int n = static_cast<int>(model->materials.size());
  const double value = Get(property, model->pair_parameters[i * n + j]) + delta;
  if (!(value >= 0 && value <= calibrate::PairPropertyMax(property))) {
    *why = std::string(calibrate::PairPropertyKey(property)) + " of " + model->materials[i].name + "-" +
           model->materials[j].name + " would be " + std::to_string(value) + ", outside [0, " +
           std::to_string(calibrate::PairPropertyMax(property)) + "]";
    return false;
  }
  calibrate::SetPairProperty(property, i, j, value, model);
  return true;
}

}  // namespace demcal::diagnose
