#include "core/bodies/unit_clump.h"

namespace demcal::core {

bool UnitDiameterClumpMembers(const std::vector<ShapeSphere>& shape,
                              std::vector<ClumpSphere>* members, std::string* error) {
  members->clear();
  for (const ShapeSphere& m : shape) members->push_back({m.centre, m.radius});
  ClumpTemplate raw;
  if (!BuildClumpTemplate(*members, 1.0, {}, &raw, error)) return false;
  const double d = raw.EquivalentVolumeDiameter();
  if (!(d > 0)) {
    if (error) *error = "the member spheres have no volume";
    return false;
  }
  const double k = 1.0 / d;
  for (ClumpSphere& m : *members) m.centre_m *= k, m.radius_m *= k;
  return true;
}

bool UnitDiameterClumpTemplate(const std::vector<ShapeSphere>& shape, ClumpTemplate* out,
                               std::string* error) {
  std::vector<ClumpSphere> members;
  return UnitDiameterClumpMembers(shape, &members, error) &&
         BuildClumpTemplate(members, 1.0, {}, out, error);
}

}  // namespace demcal::core
