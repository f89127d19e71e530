#pragma once
// The pair properties a calibration can vary (the paper's Table 1 columns and Γ): their keys in
// study files, units, physical upper limits, and the slot of the interaction table each one is.
// One more calibrated property is a species' own, not a pair's: the aspect ratio of a clumped
// species (the paper's shape, section 2.4, gives no aspect ratios, so it is calibrated). It is
// named by the pair (X, X) of the species' material and reshapes that species' clump: the same
// sphere count, re-chained on the long axis of the prolate spheroid [a, 1, 1]
// (core/bodies/clump_shapes.h). A sphere (no clump) has no aspect ratio: it is left as it is.
#include <string>

#include "core/scene/scene.h"

namespace demcal::calibrate {

enum class PairProperty {
  kSlidingFriction,
  kRollingFriction,
  kRestitution,
  kInterfacialEnergy,
  kCohesionEnergyDensity,  // sjkr's k (J/m3)
  kAspectRatio,  // of the species of material i (= j); see above
};

// The key used in study files ("sliding_friction", ...) and its unit ("", "J/m2" or "J/m3").
const char* PairPropertyKey(PairProperty property);
const char* PairPropertyUnit(PairProperty property);
double PairPropertyMax(PairProperty property);  // physical upper limit
// The minimum of the property (0 for all but the aspect ratio, 1: a sphere).
double PairPropertyMin(PairProperty property);
// Only the properties of a pair of materials (an experiment file's interaction table).
bool PairPropertyFromKey(const std::string& key, PairProperty* out);
// Every property a study may calibrate: the pair properties and the aspect ratio.
bool CalibratedPropertyFromKey(const std::string& key, PairProperty* out);

// Sets the property of the pair (i, j) and (j, i) in the model's interaction table; the aspect
// ratio reshapes every clumped species of material i instead (a value outside
// core::limits::kClumpAspectRatio leaves the shape unchanged: ParameterSpace::IsValid refuses
// such bounds before any run).
void SetPairProperty(PairProperty property, int material_i, int material_j, double value,
                     core::Scene* model);

}  // namespace demcal::calibrate
