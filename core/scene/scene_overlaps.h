#pragma once
// ExplicitOverlapError: the explicitly placed particles of a scene (Scene::particles) checked
// pairwise for a centre inside another particle (distance below the larger radius, i.e. an
// overlap deeper than the smaller radius). Coincident centres give no contact normal (NaN on the
// first step) and such overlaps are far outside Hertz's small-strain range: the run would end
// as non_finite with a misleading "time step too large". Small initial overlaps stay allowed
// (their elastic energy enters the energy budget). A particle without an explicit diameter
// counts with its species' smallest one (only certain violations are refused).
// Sort and sweep along x: O(n log n) plus the pairs within one diameter in x.
#include <string>

#include "core/scene/scene.h"

namespace demcal::core {

// "" if no explicit particle's centre lies inside another; else the message naming both.
std::string ExplicitOverlapError(const Scene& scene);

}  // namespace demcal::core
