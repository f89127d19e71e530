#pragma once
// Scene: everything that defines a DEM run, in SI units — materials, species, the pairwise
// interaction table, the contact model choice, walls, the domain, initial particles and the time
// settings. Plain data; IsValid() checks it before any work and names the offending field with
// the allowed range (field names match the JSON scene keys, e.g. "materials[1].poisson_ratio").
//
// Usage:
//   Scene s;  ...fill...;  std::string err;
//   if (!s.IsValid(&err)) { report(err); }
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "core/contact/rolling_model.h"
#include "core/insertion/factory.h"
#include "core/materials/interaction_table.h"
#include "core/insertion/insertion_region.h"
#include "core/materials/material.h"
#include "core/insertion/sink.h"
#include "core/math/quaternion.h"
#include "core/math/vec3.h"
#include "core/walls/walls.h"

namespace demcal::core {

// One explicitly placed particle.
struct ParticleSpec {
  int species = 0;
  Vec3 position_m;
  Vec3 velocity_m_s;
  Vec3 angular_velocity_rad_s;
  double diameter_m = 0;  // 0: draw from the species' size distribution
  Quaternion orientation; // of a clump (principal frame → space); identity by default
  bool fixed = false;     // glued in place (infinite mass and inertia): a rough base layer
};

// Fill a region (an axis-aligned box or a vertical cylinder: a silo) at t = 0 with `count`
// non-overlapping particles of a species at random positions (deterministic from the seed).
struct FillSpec {
  FillSpec() = default;
  FillSpec(int species_index, const Vec3& box_min_m, const Vec3& box_max_m, int64_t n,
           const Vec3& velocity = {})
      : FillSpec(species_index, InsertionRegion::Box(box_min_m, box_max_m), n, velocity) {}
  FillSpec(int species_index, const InsertionRegion& where, int64_t n, const Vec3& velocity = {})
      : species(species_index), region(where), count(n), velocity_m_s(velocity) {}

  int species = 0;
  InsertionRegion region;
  int64_t count = 0;
  Vec3 velocity_m_s;
};

struct TimeSettings {
  double duration_s = 0;          // simulated time to run
  double rayleigh_fraction = 0.2; // Δt = fraction × Rayleigh time, in (0, 1]
  double timestep_s = 0;          // > 0 overrides the fraction
  bool force_timestep = false;    // allow Δt above the Rayleigh time (not recommended)
};

struct Scene {
  std::vector<Material> materials;
  std::vector<Species> species;
  std::vector<PairParameters> pair_parameters;  // materials² entries, symmetric, row-major
  RollingModelSpec rolling;
  std::vector<Wall> walls;  // meshes already read (see ReadMeshWall); PlaneWall converts
  Vec3 domain_min_m, domain_max_m;  // a particle leaving this box ends the run (no sinks)
  std::array<bool, 3> periodic{};   // periodic boundaries along x, y, z of the domain box
  Vec3 gravity_m_s2{0, 0, -9.81};
  std::vector<ParticleSpec> particles;
  std::vector<FillSpec> fills;
  std::vector<FactorySpec> factories;
  std::vector<SinkSpec> sinks;  // see sink.h; with any, leaving the domain removes a particle
  uint64_t seed = 1;
  TimeSettings time;
  double skin_m = 0;           // Verlet skin; 0 = automatic (see NeighbourSkin)
  double max_wall_time_s = 0;  // 0 = unlimited; exceeded ⇒ termination "wall_time_exceeded"

  bool IsValid(std::string* error) const;
  int MaterialIndex(const std::string& name) const;  // -1 if absent
  int SpeciesIndex(const std::string& name) const;   // -1 if absent
  double MaxDiameter() const;
  double MinDiameter() const;
};

// Rayleigh time of the scene's stiffest, smallest sphere (docs/physics.md §1.5):
// Δt_R = π R sqrt(ρ/G) / (0.1631 ν + 0.8766), minimised over species and placed particles, with
// R a clump's smallest member sphere, shortened where its members nearly coincide and several
// touch at one point (core/bodies/contact_multiplicity.h).
double RayleighTime(const Scene& scene);

// The time step a run of the scene takes: time.timestep_s if set, else time.rayleigh_fraction ×
// RayleighTime (s).
double TimeStep(const Scene& scene);

// Largest separation a contact of the scene's normal law (SelectNormalModel) survives, over all
// material pairs, for the scene's largest spheres (m); 0 without adhesion.
double MaxAdhesiveBreakGap(const Scene& scene);

// The Verlet skin used: scene.skin_m if set, else a quarter of the smallest diameter, and in
// any case more than twice that break gap so that stretched adhesive contacts stay listed.
double NeighbourSkin(const Scene& scene);

}  // namespace demcal::core
