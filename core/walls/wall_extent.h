#pragma once
// WallExtent: where a wall's surface reaches along one world axis over its whole motion, for the
// periodic-axis check of Scene::IsValid: a wall may stand in a periodic domain only if it keeps
// a particle radius away from the periodic boundaries (it is then repeated with the domain, like
// everything else), or if it is unchanged by a shift along that axis (a plane parallel to it, an
// infinite cylinder along it). Anything else is cut by the boundary: particles wrapping around
// would pass through it or meet it from the wrong side.
//
// Units: metres. Thread-safety: pure functions.
#include "core/walls/walls.h"

namespace demcal::core {

struct AxisInterval {
  double lo_m = 0, hi_m = 0;  // ±infinity for an unbounded surface
};

// The range of the surface along axis a (0, 1, 2) at rest plus its travel: |velocity| × the
// motion's duration (up to `duration_s` for an open-ended motion).
AxisInterval WallExtent(const Wall& wall, int axis, double duration_s);

// True if shifting the wall along axis a leaves its surface unchanged.
bool InvariantAlongAxis(const Wall& wall, int axis);

}  // namespace demcal::core
