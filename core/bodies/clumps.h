#pragma once
// Clumps: the rigid multi-sphere bodies of a simulation (structure of arrays, SI units). Each
// clump owns member spheres stored in Particles (so the contact loop sees only spheres);
// Particles::body[slot] is the clump index of a member, −1 for a free sphere. Per step the
// engine moves the members with their clump (UpdateMembers), evaluates contacts on spheres, and
// reduces member forces to the clump (ReduceForces): F = M g + Σ F_s, T = Σ T_s + (x_s − x_c) × F_s.
// Members carry the clump's mass in Particles::mass_kg, so m* of a contact uses the clump mass.
//
// Thread-safety: the per-clump functions write only their own clump and its members.
#include <cstdint>
#include <vector>

#include "core/bodies/clump_template.h"
#include "core/bodies/particles.h"
#include "core/bodies/rigid_body.h"
#include "core/math/vec3.h"

namespace demcal::core {

struct Clumps {
  std::vector<Vec3> position_m;  // centre of mass
  std::vector<Vec3> velocity_m_s;
  std::vector<RigidState> rotation;           // orientation (principal → space) and L
  std::vector<Vec3> principal_inertia_kg_m2;  // (I1, I2, I3)
  std::vector<double> mass_kg;
  std::vector<Vec3> force_N, torque_N_m;
  std::vector<int> species;
  std::vector<int64_t> id;
  // Members in compressed rows: clump c owns member_slot[member_start[c] .. member_start[c+1]),
  // with body-frame offsets member_offset_m (from the centre of mass, principal frame).
  std::vector<uint32_t> member_start{0};
  std::vector<uint32_t> member_slot;
  std::vector<Vec3> member_offset_m;

  size_t Size() const { return position_m.size(); }

  template <class A>
  void Serialize(A& a) {
    a.Vector(position_m), a.Vector(velocity_m_s), a.Vector(rotation);
    a.Vector(principal_inertia_kg_m2), a.Vector(mass_kg), a.Vector(force_N), a.Vector(torque_N_m);
    a.Vector(species), a.Vector(id), a.Vector(member_start), a.Vector(member_slot);
    a.Vector(member_offset_m);
  }

  // Adds a clump of `shape` (unit equivalent-volume diameter) scaled to diameter d (m), at x
  // with orientation q, appending its member spheres to `particles`. Returns the clump index.
  size_t Add(int64_t clump_id, int species_index, int material_index, const ClumpTemplate& shape,
             double diameter_m, double density_kg_m3, const Vec3& x, const Quaternion& q,
             const Vec3& velocity, Particles& particles, int64_t& next_sphere_id);

  // Sets member positions (and velocities, spins) from the clump state.
  void UpdateMembers(size_t c, Particles& particles) const;
  // Sets member velocities and spins only, for a clump that was kicked but not moved (the lever
  // arms are read back from the member positions).
  void UpdateMemberVelocities(size_t c, Particles& particles) const;
  // Sums member forces and torques into force_N[c], torque_N_m[c] (gravity added).
  void ReduceForces(size_t c, const Particles& particles, const Vec3& gravity);
  // Updates member slots after Particles::Permute(order) (order[new] = old).
  void RemapSlots(const std::vector<uint32_t>& order);
  // Drops the clumps with gone[c] after their members were dropped from Particles by
  // Permute(order) (order[new] = old, shorter than before); returns each old clump's new index
  // (−1 if dropped).
  std::vector<int> Keep(const std::vector<uint8_t>& gone, const std::vector<uint32_t>& order);
  // Keeps the clumps order[0], order[1], ... in that order (order[new] = old; may be shorter).
  // Member slots are unchanged: Particles::body must be renumbered by the caller.
  void Select(const std::vector<uint32_t>& order);

  Vec3 AngularVelocity(size_t c) const {
    return demcal::core::AngularVelocity(rotation[c], principal_inertia_kg_m2[c]);
  }
  double KineticEnergy(size_t c) const;
};

}  // namespace demcal::core
