#include "diagnose/effects/effect_registry.h"

namespace demcal::diagnose {

const std::vector<const Effect*>& EffectLibrary() {
  static const std::vector<const Effect*> library = {
      JkrAdhesionEffect(),
      SjkrCohesionEffect(),
      RollingResistanceEffect(),
      ParticleShapeEffect(),
      SizePolydispersityEffect(),
      WallFrictionEffect(),
      SlidingFrictionControlEffect(),
  };
  return library;
}

const Effect* FindEffect(const std::string& key) {
  for (const Effect* e : EffectLibrary())
    if (e->Key() == key) return e;
  return nullptr;
}

std::string EffectKeys() {
  std::string keys;
  for (const Effect* e : EffectLibrary()) keys += (keys.empty() ? "" : ", ") + e->Key();
  return keys;
}

}  // namespace demcal::diagnose
