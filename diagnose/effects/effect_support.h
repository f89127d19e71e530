#pragma once
// Helpers the effect files share: find the subject species and its material in a model, and
// shift a pair property of the interaction table (both orders) within its physical range.
#include <string>

#include "calibrate/condition.h"
#include "calibrate/pair_property.h"
#include "core/scene/scene.h"
#include "diagnose/effects/effect.h"

namespace demcal::diagnose {

// JKR adhesion's probe and upper bound at the largest coating level (J/m², full scale), whose
// reasons jkr_adhesion.cc gives; the sjkr candidate converts them (sjkr_cohesion.cc).
inline constexpr double kJkrProbeGamma_J_m2 = 0.01;
inline constexpr double kJkrUpperGamma_J_m2 = 0.03;

// Index of the context's species (or material) in the model; false with why if absent.
bool FindSpecies(const core::Scene& model, const EffectContext& context, int* species, std::string* why);
bool FindMaterial(const core::Scene& model, const std::string& name, int* material, std::string* why);
// pair(i, j) property += delta, in both orders; false when the result leaves [0, max].
bool ShiftPairProperty(calibrate::PairProperty property, int i, int j, double delta, core::Scene* model,
                       std::string* why);

// An adhesion effect's scale: its value is per unit of the coating column at the largest level
// when the data have one (1 otherwise). The parameter's name: `plain` without a coating column,
// else `per_stem` + "_per_<column>_" + unit_suffix ("gamma_per_coating_PEG_wt_pct_J_m2").
double CoatingScale(const EffectContext& context);
std::string CoatingScaledName(const EffectContext& context, const std::string& plain,
                              const std::string& stem, const std::string& unit_suffix);
// The species' self-contact `property` += per_level × the condition's coating level (× 1 without
// a coating column; an uncoated condition, with no level, gets 0). False with why when the
// result leaves the property's range or makes the model call for two normal laws (JKR's Γ and
// sjkr's k: a scene runs one).
bool ShiftSelfContactWithCoating(calibrate::PairProperty property, double per_level,
                                 const calibrate::Condition& condition,
                                 const EffectContext& context, core::Scene* model,
                                 std::string* why);

}  // namespace demcal::diagnose
