#pragma once
// OrderById: the storage slots of a particle set sorted by stable particle id. The engine
// reorders its slots for cache locality, so every writer that wants reproducible files (the same
// row for the same particle in every snapshot) walks the particles in this order. BodyId: which
// rigid body (free sphere or clump) a sphere belongs to.
#include <algorithm>
#include <cstddef>
#include <numeric>
#include <vector>

#include "core/bodies/clumps.h"
#include "core/bodies/particles.h"

namespace demcal::core::io {

inline std::vector<size_t> OrderById(const Particles& particles) {
  std::vector<size_t> order(particles.Size());
  std::iota(order.begin(), order.end(), size_t{0});
  std::sort(order.begin(), order.end(),
            [&](size_t a, size_t b) { return particles.id[a] < particles.id[b]; });
  return order;
}

// The id of the rigid body each sphere slot belongs to: its own id for a free sphere, its
// clump's id for a clump member (`clumps` may be null when there are none).
inline int64_t BodyId(const Particles& particles, const Clumps* clumps, size_t slot) {
  const int body = slot < particles.body.size() ? particles.body[slot] : -1;
  return body >= 0 && clumps ? clumps->id[body] : particles.id[slot];
}

}  // namespace demcal::core::io
