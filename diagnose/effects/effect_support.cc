#include "diagnose/effects/effect_support.h"

#include "core/contact/normal_model.h"

namespace demcal::diagnose {
namespace {

double Get(calibrate::PairProperty property, const core::PairParameters& p) {
  switch (property) {
    case calibrate::PairProperty::kSlidingFriction: return p.sliding_friction;
    case calibrate::PairProperty::kRollingFriction: return p.rolling_friction;
    case calibrate::PairProperty::kRestitution: return p.restitution;
    case calibrate::PairProperty::kInterfacialEnergy: return p.interfacial_energy_J_m2;
    case calibrate::PairProperty::kCohesionEnergyDensity: return p.cohesion_energy_density_J_m3;
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

double CoatingScale(const EffectContext& c) {
  return c.coating_column.empty() ? 1.0 : c.coating_max;
}

std::string CoatingScaledName(const EffectContext& c, const std::string& plain,
                              const std::string& stem, const std::string& unit_suffix) {
  return c.coating_column.empty() ? plain : stem + "_per_" + c.coating_column + "_" + unit_suffix;
}

bool ShiftSelfContactWithCoating(calibrate::PairProperty property, double per_level,
                                 const calibrate::Condition& condition, const EffectContext& c,
                                 core::Scene* model, std::string* why) {
  int m = 0;
  if (!FindMaterial(*model, c.material, &m, why)) return false;
  double level = 1;
  if (!c.coating_column.empty() && !calibrate::ConditionNumber(condition, c.coating_column, &level))
    level = 0;
  if (!ShiftPairProperty(property, m, m, per_level * level, model, why)) return false;
  // One normal law per scene (core/contact/normal_model.h): an adhesion law added to a model
  // with the other one is refused here, before any run, rather than by every run's validation.
  const auto laws = core::NormalLawsCalledFor(model->pair_parameters);
  if (laws.size() < 2) return true;
  *why = "the model would call for two adhesion laws, " + laws[0].first + " and " +
         laws[1].first + "; a scene runs one";
  return false;
}

}  // namespace demcal::diagnose
