#pragma once
// One wall of a scene checked for Scene::IsValid (core/scene/scene_validation.cc): its material,
// its surface's own ranges, its sizes against the limits table, its extent inside the domain
// and not across a periodic axis over the run, and its motion. A surface's IsValid message
// "cylinder: radius_m must be ..." becomes "field 'walls[2].radius_m' must be ...
// (cylinder 'silo')".
#include <cstddef>

#include "core/scene/field_checker.h"

namespace demcal::core {

struct Scene;

void CheckSceneWall(const Scene& s, size_t i, FieldChecker& c);

}  // namespace demcal::core
