#pragma once
// GluedBase: a layer of fixed spheres on the floor of a test, so that the first layer of a heap
// cannot slide or roll away on a smooth plate (a flat frictional wall under a heap gives a
// too-low, base-dependent angle). The spheres sit on a square lattice of pitch d, each lifted
// by a random fraction of its radius, which gives a random roughness of the particle scale.
#include <cstdint>
#include <vector>

#include "core/scene/scene.h"
#include "objectives/common/feed.h"

namespace demcal::objectives {

struct GluedBaseSpec {
  int species = 0;          // the layer's species (its material touches the heap)
  double diameter_m = 0;    // > 0
  core::Vec3 min_m, max_m;  // x–y rectangle of the layer; z of min_m = the floor
  double disc_radius_m = 0; // > 0: keep only lattice points within this radius of the centre
  uint64_t seed = 1;
};

// A layer of the feed's first species at its mean sieve diameter, seeded from the run's seed;
// the caller sets the extent (min_m, max_m, disc_radius_m).
GluedBaseSpec GluedBaseOfFeed(const core::Scene& model, const Feed& feed, uint64_t seed);

// Fixed particles are spheres: when spec->species is a clump species, appends to `scene` a sphere
// species of the same material at spec->diameter_m (named "<species> glued base") and points
// spec->species at it, so a clump feed (the clump-count calibration) still gets its glued layer.
void UseSphereSpeciesForBase(core::Scene* scene, GluedBaseSpec* spec);

// The fixed particles of the layer (ParticleSpec::fixed = true).
std::vector<core::ParticleSpec> GluedBase(const GluedBaseSpec& spec);

// Mean height of the layer's top (centres at 1.25 r on average, plus a radius): the heap base
// of the angle measurement.
inline double GluedBaseTop(const GluedBaseSpec& spec) {
  return spec.min_m.z + 1.125 * spec.diameter_m;
}

}  // namespace demcal::objectives
