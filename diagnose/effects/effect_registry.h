#pragma once
// The library of candidate effects the diagnosis holds the residuals against (effect.h). One
// file per effect in this folder; one line per effect in effect_registry.cc.
//
//   for (const Effect* e : EffectLibrary()) ...;
//   const Effect* e = FindEffect("jkr_adhesion");  // nullptr if unknown
//
// Thread-safety: the effects are immutable singletons.
#include <string>
#include <vector>

#include "diagnose/effects/effect.h"

namespace demcal::diagnose {

const Effect* JkrAdhesionEffect();
const Effect* SjkrCohesionEffect();
const Effect* RollingResistanceEffect();
const Effect* ParticleShapeEffect();
const Effect* SizePolydispersityEffect();
const Effect* WallFrictionEffect();
const Effect* SlidingFrictionControlEffect();

const std::vector<const Effect*>& EffectLibrary();
const Effect* FindEffect(const std::string& key);
// "jkr_adhesion, rolling_resistance, ..."
std::string EffectKeys();

}  // namespace demcal::diagnose
