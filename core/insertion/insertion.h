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

// A clump draw of an earlier batch that found no room, kept to be placed later: its species (an
// index into InsertionRequest::mixture) and equivalent diameter. Two 8-byte fields, no padding,
// so a checkpoint stores it raw with no undefined bytes.
struct CarriedDraw {
  int64_t mixture_index = 0;
  double diameter_m = 0;
  bool operator==(const CarriedDraw&) const = default;
};

struct InsertionRequest {
  InsertionRegion region;
  std::vector<SpeciesDraw> mixture;  // non-empty
  // Clump batches only: draws carried from earlier batches. They join this batch's draws (their
  // mass counts toward max_mass_kg) and are placed in the same largest-first order.
  std::vector<CarriedDraw> carried;
  int64_t max_count = std::numeric_limits<int64_t>::max();
  double max_mass_kg = std::numeric_limits<double>::infinity();  // stop once reached
  Vec3 velocity_m_s;
  int max_attempts_per_particle = 2000;
};

struct InsertionResult {
  int64_t count = 0;
  double mass_kg = 0;
  bool region_full = false;  // a particle could not be placed within its attempts
  // Clump batches only: the draws that found no room, in placement order (to be carried).
  std::vector<CarriedDraw> unplaced;
};

// Appends particles (spheres or clumps, by species, clumps randomly oriented) until max_count
// or max_mass_kg is reached or the region is full. A clump's enclosing sphere lies inside the
// region, and its members (randomly oriented) overlap no sphere already present. A batch of
// finite mass holding clumps is drawn whole (with the carried draws), every draw is tried once,
// largest first, and those that find no room come back in `unplaced`; a sphere batch stops at
// its first particle that finds no room (that draw is not returned).
InsertionResult InsertRandomNonOverlapping(const InsertionRequest& request, Rng& rng,
                                           ParticleSystem& system);

// The mass of a body of `draw` at (equivalent) diameter d: ParticleSystem::Add's, to rounding.
double DrawMassKg(const ParticleSystem& system, const SpeciesDraw& draw, double d);

// Number weights that realise the given mass fractions (w_s / mean particle mass_s).
std::vector<double> NumberWeightsFromMassFractions(const std::vector<double>& mass_fractions,
                                                   const std::vector<double>& mean_mass_kg);

}  // namespace demcal::core
