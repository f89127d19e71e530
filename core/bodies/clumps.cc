#include "core/bodies/clumps.h"

#include <algorithm>

namespace demcal::core {

size_t Clumps::Add(int64_t clump_id, int species_index, int material_index,
                   const ClumpTemplate& shape, double d, double density, const Vec3& x,
                   const Quaternion& q, const Vec3& velocity, Particles& particles,
                   int64_t& next_sphere_id) {
  const size_t c = Size();
  // The template has unit equivalent-volume diameter and unit density: mass ∝ ρd³, I ∝ ρd⁵.
  const double mass = shape.mass_kg * density * d * d * d;
  position_m.push_back(x);
  velocity_m_s.push_back(velocity);
  rotation.push_back({q, {}});
  principal_inertia_kg_m2.push_back(shape.principal_inertia_kg_m2 * (density * d * d * d * d * d));
  mass_kg.push_back(mass);
  force_N.push_back({});
  torque_N_m.push_back({});
  species.push_back(species_index);
  id.push_back(clump_id);
  for (const ClumpSphere& s : shape.spheres) {
    const Vec3 offset = s.centre_m * d;
    const size_t slot = particles.Add(next_sphere_id++, species_index, material_index,
                                      s.radius_m * d, density, x + Rotate(q, offset), velocity, {});
    particles.body[slot] = static_cast<int>(c);
    particles.mass_kg[slot] = mass;  // contacts see the clump's mass (m*)
    particles.inv_mass[slot] = 0;    // members are moved by their clump, not integrated
    particles.inv_inertia[slot] = 0;
    member_slot.push_back(static_cast<uint32_t>(slot));
    member_offset_m.push_back(offset);
  }
  member_start.push_back(static_cast<uint32_t>(member_slot.size()));
  return c;
}

void Clumps::UpdateMembers(size_t c, Particles& p) const {
  const Vec3 omega = AngularVelocity(c);
  const Quaternion& q = rotation[c].orientation;
  for (uint32_t k = member_start[c]; k < member_start[c + 1]; ++k) {
    const uint32_t s = member_slot[k];
    const Vec3 arm = Rotate(q, member_offset_m[k]);
    p.position_m[s] = position_m[c] + arm;
    p.velocity_m_s[s] = velocity_m_s[c] + Cross(omega, arm);
    p.angular_velocity_rad_s[s] = omega;
  }
}

void Clumps::UpdateMemberVelocities(size_t c, Particles& p) const {
  const Vec3 omega = AngularVelocity(c);
  for (uint32_t k = member_start[c]; k < member_start[c + 1]; ++k) {
    const uint32_t s = member_slot[k];
    p.velocity_m_s[s] = velocity_m_s[c] + Cross(omega, p.position_m[s] - position_m[c]);
    p.angular_velocity_rad_s[s] = omega;
  }
}

void Clumps::ReduceForces(size_t c, const Particles& p, const Vec3& gravity) {
  Vec3 f = gravity * mass_kg[c], t;
  for (uint32_t k = member_start[c]; k < member_start[c + 1]; ++k) {
    const uint32_t s = member_slot[k];
    f += p.force_N[s];
    t += p.torque_N_m[s] + Cross(p.position_m[s] - position_m[c], p.force_N[s]);
  }
  force_N[c] = f;
  torque_N_m[c] = t;
}

void Clumps::RemapSlots(const std::vector<uint32_t>& order) {
  if (order.empty() || member_slot.empty()) return;
  std::vector<uint32_t> new_slot_of_old(order.size());
  for (uint32_t k = 0; k < order.size(); ++k) new_slot_of_old[order[k]] = k;
  for (uint32_t& s : member_slot) s = new_slot_of_old[s];
}

namespace {
template <typename T>
void ApplyClumpOrder(std::vector<T>& v, const std::vector<uint32_t>& order) {
  std::vector<T> out(order.size());
  for (size_t k = 0; k < order.size(); ++k) out[k] = v[order[k]];
  v.swap(out);
}
}  // namespace

void Clumps::Select(const std::vector<uint32_t>& order) {
  std::vector<uint32_t> start{0}, slots;
  std::vector<Vec3> offsets;
  slots.reserve(member_slot.size()), offsets.reserve(member_slot.size());
  for (uint32_t c : order) {
    for (uint32_t k = member_start[c]; k < member_start[c + 1]; ++k) {
      slots.push_back(member_slot[k]);
      offsets.push_back(member_offset_m[k]);
    }
    start.push_back(static_cast<uint32_t>(slots.size()));
  }
  ApplyClumpOrder(position_m, order), ApplyClumpOrder(velocity_m_s, order);
  ApplyClumpOrder(rotation, order), ApplyClumpOrder(principal_inertia_kg_m2, order);
  ApplyClumpOrder(mass_kg, order), ApplyClumpOrder(force_N, order);
  ApplyClumpOrder(torque_N_m, order), ApplyClumpOrder(species, order);
  ApplyClumpOrder(id, order);
  member_start.swap(start), member_slot.swap(slots), member_offset_m.swap(offsets);
}

std::vector<int> Clumps::Keep(const std::vector<uint8_t>& gone, const std::vector<uint32_t>& order) {
  std::vector<int> new_index(Size(), -1);
  std::vector<uint32_t> kept;
  for (size_t c = 0; c < Size(); ++c)
    if (!gone[c]) new_index[c] = static_cast<int>(kept.size()), kept.push_back(c);
  Select(kept);
  uint32_t old_slots = 0;
  for (uint32_t s : member_slot) old_slots = std::max(old_slots, s + 1);
  for (uint32_t s : order) old_slots = std::max(old_slots, s + 1);
  std::vector<uint32_t> new_slot_of_old(old_slots, 0);
  for (uint32_t k = 0; k < order.size(); ++k) new_slot_of_old[order[k]] = k;
  for (uint32_t& s : member_slot) s = new_slot_of_old[s];
  return new_index;
}

double Clumps::KineticEnergy(size_t c) const {
  return 0.5 * mass_kg[c] * Norm2(velocity_m_s[c]) +
         RotationalKineticEnergy(rotation[c], principal_inertia_kg_m2[c]);
}

}  // namespace demcal::core
