#pragma once
// The pair properties a calibration can vary (the paper's Table 1 columns and Γ): their keys in
// study files, units, physical upper limits, and the slot of the interaction table each one is.
#include <string>

#include "core/scene/scene.h"

namespace demcal::calibrate {

enum class PairProperty { kSlidingFriction, kRollingFriction, kRestitution, kInterfacialEnergy };

// The key used in study files ("sliding_friction", ...) and its unit ("" or "J/m2").
const char* PairPropertyKey(PairProperty property);
const char* PairPropertyUnit(PairProperty property);
double PairPropertyMax(PairProperty property);  // physical upper limit
bool PairPropertyFromKey(const std::string& key, PairProperty* out);

// Sets the property of the pair (i, j) and (j, i) in the model's interaction table.
void SetPairProperty(PairProperty property, int material_i, int material_j, double value,
                     core::Scene* model);

}  // namespace demcal::calibrate
