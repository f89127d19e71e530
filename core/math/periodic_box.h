#pragma once
// PeriodicBox: periodic boundary conditions along chosen axes of the domain box. A length of 0
// on an axis means "not periodic". Pair separations use the minimum image; positions of free
// particles and clump centres are wrapped back into [min, min + length).
#include <cmath>

#include "core/math/vec3.h"

namespace demcal::core {

struct PeriodicBox {
  Vec3 origin_m;  // domain minimum
  Vec3 length_m;  // period along x, y, z; 0 = not periodic

  bool Any() const { return length_m.x > 0 || length_m.y > 0 || length_m.z > 0; }
  bool IsPeriodic(int axis) const { return length_m[axis] > 0; }

  Vec3 MinimumImage(Vec3 d) const {
    for (int a = 0; a < 3; ++a)
      if (length_m[a] > 0) d[a] -= length_m[a] * std::nearbyint(d[a] / length_m[a]);
    return d;
  }
  Vec3 Wrap(Vec3 x) const {
    for (int a = 0; a < 3; ++a)
      if (length_m[a] > 0) {
        x[a] -= length_m[a] * std::floor((x[a] - origin_m[a]) / length_m[a]);
      }
    return x;
  }
};

}  // namespace demcal::core
