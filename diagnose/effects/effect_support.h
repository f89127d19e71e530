#pragma once
// Helpers the effect files share: find the subject species and its material in a model, and
// shift a pair property of the interaction table (both orders) within its physical range.
#include <string>

#include "calibrate/pair_property.h"
#include "core/scene/scene.h"
#include "diagnose/effects/effect.h"

namespace demcal::diagnose {

// Index of the context's species (or material) in the model; false with why if absent.
bool FindSpecies(const core::Scene& model, const EffectContext& context, int* species, std::string* why);
bool FindMaterial(const core::Scene& model, const std::string& name, int* material, std::string* why);
// pair(i, j) property += delta, in both orders; false when the result leaves [0, max].
bool ShiftPairProperty(calibrate::PairProperty property, int i, int j, double delta, core::Scene* model,
                       std::string* why);

}  // namespace demcal::diagnose
