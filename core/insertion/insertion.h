#pragma once
// Insertion of particles at random non-overlapping positions (random sequential addition with
// a cell grid that also sees the particles already present). Deterministic for a given Rng
// state. Used by scene fills at t = 0 and by the rate-controlled factories.
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "core/insertion/insertion_region.h"
#include "core/materials/material.h"
#include "core/bodies/particle_system.h"
#include "core/math/random.h"
#include "core/math/vec3.h"

namespace demcal::core {

// One species a request may draw, with its relative number weight.
struct SpeciesDraw {
  int species = 0;
  int material = 0;
  double density_kg_m3 = 0;
  const SizeDistribution* size = nullptr;
  double number_weight = 1;
};

struct InsertionRequest {
  InsertionRegion region;
  std::vector<SpeciesDraw> mixture;  // non-empty
  int64_t max_count = std::numeric_limits<int64_t>::max();
  double max_mass_kg = std::numeric_limits<double>::infinity();  // stop once reached
  Vec3 velocity_m_s;
  int max_attempts_per_particle = 2000;
};

struct InsertionResult {
  int64_t count = 0;
  double mass_kg = 0;
  bool region_full = false;  // a particle could not be placed within its attempts
};

// Appends particles (spheres or clumps, by species, clumps randomly oriented) until max_count
// or max_mass_kg is reached or the region is full. A clump's enclosing sphere lies inside the
// region, and its members (randomly oriented) overlap no sphere already present.
InsertionResult InsertRandomNonOverlapping(const InsertionRequest& request, Rng& rng,
                                           ParticleSystem& system);

// Number weights that realise the given mass fractions (w_s / mean particle mass_s).
std::vector<double> NumberWeightsFromMassFractions(const std::vector<double>& mass_fractions,
                                                   const std::vector<double>& mean_mass_kg);

}  // namespace demcal::core
