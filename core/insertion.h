#pragma once
// Insertion of particles at random non-overlapping positions (random sequential addition with
// a cell grid). Deterministic for a given Rng state. Used by scene fills at t = 0; the
// rate-controlled factories of DEM core II build on it.
#include <cstdint>
#include <string>

#include "core/material.h"
#include "core/particles.h"
#include "core/random.h"
#include "core/vec3.h"

namespace demcal::core {

struct BoxRegion {
  Vec3 min_m, max_m;
};

struct InsertionRequest {
  BoxRegion region;        // particle centres are kept a radius inside it
  int species = 0;
  int material = 0;
  double density_kg_m3 = 0;
  const SizeDistribution* size = nullptr;
  int64_t count = 0;
  Vec3 velocity_m_s;
  int max_attempts_per_particle = 2000;
};

// Appends up to request.count particles to `particles`, giving them ids from `next_id`.
// Returns the number placed; if fewer than requested, `error` explains (region too small).
int64_t InsertRandomNonOverlapping(const InsertionRequest& request, Rng& rng, Particles& particles,
                                   int64_t& next_id, std::string* error);

}  // namespace demcal::core
