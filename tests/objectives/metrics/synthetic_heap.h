#pragma once
// Synthetic heaps for the segregation metric tests: grains placed uniformly at random in a
// triangular heap (base [0, width] at z = 0, apex at the centre) through a box of given depth.
#include <cmath>
#include <functional>
#include <numbers>
#include <vector>

#include "core/math/random.h"
#include "objectives/common/snapshot.h"

namespace demcal::objectives::testing {

struct SyntheticHeap {
  double width_m = 0.12;
  double height_m = 0.06;
  double depth_m = 0.016;
  double radius_m = 0.0005;
  double density_kg_m3 = 1000;
};

// Species of a grain at a position; `rng` gives the randomness of a random mixture.
using SpeciesRule = std::function<int(const core::Vec3& position_m, core::Rng& rng)>;

inline bool InsideTriangle(const SyntheticHeap& heap, double x, double z) {
  const double half = heap.width_m / 2;
  return z >= 0 && z <= heap.height_m * (1 - std::abs(x - half) / half);
}

// `count` grains, each with one surface sphere, placed uniformly inside the triangle.
inline Snapshot MakeHeap(const SyntheticHeap& heap, int count, uint64_t seed,
                         const SpeciesRule& species) {
  core::Rng rng(seed);
  Snapshot snap;
  const double volume = 4.0 / 3.0 * std::numbers::pi * std::pow(heap.radius_m, 3);
  while (static_cast<int>(snap.grains.size()) < count) {
    const core::Vec3 p{rng.Uniform(0, heap.width_m), rng.Uniform(0, heap.depth_m),
                       rng.Uniform(0, heap.height_m)};
    if (!InsideTriangle(heap, p.x, p.z)) continue;
    Grain g;
    g.id = static_cast<int64_t>(snap.grains.size());
    g.species = species(p, rng);
    g.position_m = p;
    g.radius_m = heap.radius_m;
    g.mass_kg = heap.density_kg_m3 * volume;
    snap.spheres.push_back({p, heap.radius_m, static_cast<int>(snap.grains.size())});
    snap.grains.push_back(g);
  }
  return snap;
}

// Species 0, 1, 2 with probabilities 1 − p1 − p2, p1, p2, independent of position.
inline SpeciesRule RandomSpecies(double p1, double p2) {
  return [p1, p2](const core::Vec3&, core::Rng& rng) {
    const double u = rng.Uniform();
    return u < p2 ? 2 : (u < p2 + p1 ? 1 : 0);
  };
}

}  // namespace demcal::objectives::testing
