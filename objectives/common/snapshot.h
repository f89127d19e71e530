#pragma once
// Snapshot: what the virtual-experiment metrics see of a DEM state — one Grain per particle (a
// free sphere or a whole clump) and the member spheres that make up the visible surface. Plain
// data in SI units, so every metric is a pure function testable on constructed snapshots without
// running DEM.
//
// Axis convention of the experiments: gravity along −z; a pseudo-2D box spans x (width) and z
// (height), its thin depth is y; the front face is at the box's y_min, the back face at y_max.
#include <cstdint>
#include <functional>
#include <vector>
#include "core/math/vec3.h"

namespace demcal::core {
class Simulation;
}

namespace demcal::objectives {

using core::Vec3;

struct Grain {
  int64_t id = 0;         // stable particle (or clump) identity
  int species = 0;        // index into the scene's species
  Vec3 position_m;        // centre of mass
  Vec3 velocity_m_s;      // of the centre of mass
  double radius_m = 0;    // volume-equivalent radius
  double mass_kg = 0;
};

// A sphere as it occupies space: a free sphere, or one member of a clump (grain = its Grain's
// index in Snapshot::grains).
struct SurfaceSphere {
  Vec3 position_m;
  double radius_m = 0;
  int grain = 0;
};

struct Snapshot {
  double time_s = 0;
  std::vector<Grain> grains;
  std::vector<SurfaceSphere> spheres;
};

// The current state of a simulation as a Snapshot (grains ordered by id).
Snapshot TakeSnapshot(const core::Simulation& simulation);

// The grains for which keep(grain) is true, with their spheres.
Snapshot Select(const Snapshot& snapshot, const std::function<bool(const Grain&)>& keep);

// Grains with a centre inside the axis-aligned box [lo, hi] (e.g. the heap, not the funnel).
Snapshot Crop(const Snapshot& snapshot, const Vec3& lo_m, const Vec3& hi_m);

}  // namespace demcal::objectives
