#pragma once
// OrderById: the storage slots of a particle set sorted by stable particle id. The engine
// reorders its slots for cache locality, so every writer that wants reproducible files (the same
// row for the same particle in every snapshot) walks the particles in this order.
#include <algorithm>
#include <cstddef>
#include <numeric>
#include <vector>

#include "core/particles.h"

namespace demcal::core::io {

inline std::vector<size_t> OrderById(const Particles& particles) {
  std::vector<size_t> order(particles.Size());
  std::iota(order.begin(), order.end(), size_t{0});
  std::sort(order.begin(), order.end(),
            [&](size_t a, size_t b) { return particles.id[a] < particles.id[b]; });
  return order;
}

}  // namespace demcal::core::io
