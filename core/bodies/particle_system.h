#pragma once
// ParticleSystem: every moving body of a simulation — free spheres and clumps (whose member
// spheres also live in `spheres`, so contacts only ever see spheres) — plus the per-species
// clump shapes, with the operations that treat both kinds alike: adding a particle of a
// species, energies, and the velocity-Verlet kick and drift.
//
// Thread-safety: the kick/drift functions run TBB loops over disjoint bodies.
#include <cstdint>
#include <string>
#include <vector>

#include "core/bodies/clumps.h"
#include "core/materials/material.h"
#include "core/bodies/particles.h"
#include "core/math/periodic_box.h"
#include "core/math/quaternion.h"

namespace demcal::core {

struct ParticleSystem {
  Particles spheres;
  Clumps clumps;
  // Per species: the clump shape at unit equivalent-volume diameter and unit density, or an
  // empty template (no spheres) for a plain sphere species.
  std::vector<ClumpTemplate> shapes;
  int64_t next_id = 0;  // ids are shared by spheres and clump members

  // Checkpointing (shapes are rebuilt from the scene, not stored).
  template <class A>
  void Serialize(A& a) {
    spheres.Serialize(a);
    clumps.Serialize(a);
    a.Value(next_id);
  }

  // Builds `shapes` from the species definitions; false with a message naming the species.
  bool SetSpecies(const std::vector<Species>& species, std::string* error);
  bool IsClump(int species) const { return !shapes[species].spheres.empty(); }
  // Radius of the sphere enclosing a particle of the species with (equivalent) diameter d.
  double EnclosingRadius(int species, double diameter_m) const;

  // Adds one particle (sphere or clump) of a species; `q` orients a clump.
  void Add(int species, int material, double density_kg_m3, double diameter_m, const Vec3& x,
           const Vec3& v, const Vec3& omega, const Quaternion& q);

  double KineticEnergy() const;
  // −Σ m g·x over bodies (clumps at their centre of mass), J.
  double GravitationalPotential(const Vec3& gravity) const;
  // Σ m g·(x_low − x): energy released if every body dropped to the point x_low, J; over the
  // bodies from sphere slot `first_sphere` and clump `first_clump` on (newcomers).
  double ReleasableGravitationalEnergy(const Vec3& gravity, const Vec3& lowest,
                                       size_t first_sphere = 0, size_t first_clump = 0) const;
  // Bodies (free spheres + clumps) from sphere slot `first_sphere` and clump `first_clump` on.
  double KineticEnergySince(size_t first_sphere, size_t first_clump) const;

  // Velocity Verlet: first half kick and drift (members follow their clumps) ...
  // Only sphere slots [0, moving_spheres) are visited: the engine keeps fixed spheres after them.
  // `finish_last_kick`: the free spheres' second half kick of the previous step, deferred by
  // ReduceAndKick, is done first in the same pass.
  void KickDrift(double dt, size_t moving_spheres, bool finish_last_kick = false);
  // ... and, after forces, the second half kick (clump forces reduced from their members).
  // `defer_sphere_kick`: the free spheres' half kick is left to the next KickDrift (or
  // FinishKick), so their state is streamed through memory once per step instead of twice; the
  // same operations run in the same order, so the results are unchanged. Until then their
  // velocities are half a kick behind: only for steps followed directly by another step.
  void ReduceAndKick(const Vec3& gravity, double dt, size_t moving_spheres,
                     bool defer_sphere_kick = false);
  // The deferred half kick alone (before anything reads the velocities).
  void FinishKick(double dt, size_t moving_spheres);
  // Clump forces and torques from their members' (needed once before the first step).
  void ReduceClumpForces(const Vec3& gravity);
  // Wraps free spheres and clump centres back into the periodic box (members follow).
  void WrapPeriodic(const PeriodicBox& box);
  // `order` (order[new] = old slot, all slots) with each clump's members moved, in member
  // order, to where its first member appears: members become contiguous slots.
  std::vector<uint32_t> GroupClumpMembers(const std::vector<uint32_t>& order) const;
  // Reorders sphere slots (Particles::Permute) and keeps clump member slots consistent; clumps
  // are renumbered in the order of their first member's slot (the clump loops then stream).
  void Permute(const std::vector<uint32_t>& order);
  // Removes free spheres with sphere_gone[slot] and clumps with clump_gone[c] (with all their
  // members; their members' sphere_gone entries are ignored). The remaining slots keep their
  // order; returns the old slot of each new one (order[new] = old) for history transfer.
  std::vector<uint32_t> Remove(const std::vector<uint8_t>& sphere_gone,
                               const std::vector<uint8_t>& clump_gone);
  size_t BodyCount() const;
};

// A uniformly distributed random orientation from three uniform variates (Shoemake 1992).
Quaternion UniformRandomOrientation(double u1, double u2, double u3);

}  // namespace demcal::core
