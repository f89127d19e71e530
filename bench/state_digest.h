#pragma once
// An order-independent digest of the particles' state: equal across thread counts iff the runs
// are bit-identical (in practice; it is a sum of positions and velocities weighted by id).
#include "core/bodies/particles.h"

namespace demcal::bench {

inline double StateDigest(const core::Particles& p) {
  double digest = 0;
  for (size_t i = 0; i < p.Size(); ++i)
    digest += p.position_m[i].x * (1 + p.id[i] % 7) + p.velocity_m_s[i].z;
  return digest;
}

}  // namespace demcal::bench
