#pragma once
// Particles: the contiguous per-sphere state of a simulation (structure of arrays, SI units).
// Index i is a storage slot that may change when the engine reorders particles for cache
// locality; `id` is the stable identity written to every output.
//
// Thread-safety: the engine writes disjoint slots from parallel loops; no internal locking.
#include <cstdint>
#include <vector>

#include "core/math/vec3.h"

namespace demcal::core {

struct Particles {
  std::vector<Vec3> position_m;
  std::vector<Vec3> velocity_m_s;
  std::vector<Vec3> angular_velocity_rad_s;
  std::vector<Vec3> force_N;
  std::vector<Vec3> torque_N_m;
  std::vector<double> radius_m;
  std::vector<double> mass_kg;
  std::vector<double> inv_mass;     // 1/kg
  std::vector<double> inv_inertia;  // 1/(kg m²), solid sphere I = (2/5) m R²
  std::vector<int> species;
  std::vector<int> material;
  std::vector<int> body;  // clump index of a clump member, −1 for a free sphere
  std::vector<int64_t> id;

  size_t Size() const { return position_m.size(); }
  // A glued sphere (Fix): no inverse mass and not a clump member (members have none either).
  bool IsFixed(size_t i) const { return inv_mass[i] == 0 && body[i] < 0; }
  // How many of slots [first, last) are not fixed (in parallel: a rebuild asks every time).
  size_t CountMoving(size_t first, size_t last) const;

  template <class A>
  void Serialize(A& a) {
    a.Vector(position_m), a.Vector(velocity_m_s), a.Vector(angular_velocity_rad_s);
    a.Vector(force_N), a.Vector(torque_N_m), a.Vector(radius_m), a.Vector(mass_kg);
    a.Vector(inv_mass), a.Vector(inv_inertia), a.Vector(species), a.Vector(material);
    a.Vector(body), a.Vector(id);
  }

  // Appends one sphere at rest-or-moving state; returns its slot.
  size_t Add(int64_t particle_id, int species_index, int material_index, double radius,
             double density, const Vec3& position, const Vec3& velocity, const Vec3& omega);

  // Glues slot i in place: zero velocity, infinite mass and inertia (inv_mass = inv_inertia = 0),
  // so contacts push on it but it never moves (a rough base layer of fixed spheres). Contact
  // damping still uses its real mass in m*, so restitution against it is approximate. Its force
  // and torque are zeroed: the engine no longer computes them (Simulation::Options).
  void Fix(size_t i);
  // Reorders every per-particle array so that new slot k holds old slot order[k]; an order
  // shorter than Size() drops the slots it does not name.
  void Permute(const std::vector<uint32_t>& order);

  // Translational + rotational kinetic energy of sphere i if it is free (0 for a clump member,
  // whose energy is its clump's, and for a fixed sphere), J.
  double FreeKineticEnergy(size_t i) const;
  // Translational + rotational kinetic energy of the free spheres (clump members excluded), J.
  double KineticEnergy() const;
};

}  // namespace demcal::core
