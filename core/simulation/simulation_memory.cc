// Simulation::Heap: the bytes its arrays hold, for memory estimates (demcal_bench memory).
#include "core/simulation/simulation.h"

namespace demcal::core {

HeapBytes Simulation::Heap() const {
  HeapBytes b = list_.Heap();
  b += spare_list_.Heap();
  b += compacted_list_.Heap();
  b += forces_.Heap();
  const Particles& p = system_.spheres;
  const Clumps& c = system_.clumps;
  b.per_particle += VectorBytes(p.position_m, p.velocity_m_s, p.angular_velocity_rad_s, p.force_N,
                                p.torque_N_m, p.radius_m, p.mass_kg, p.inv_mass, p.inv_inertia) +
                    VectorBytes(p.species, p.material, p.body, p.id);
  b.per_particle += VectorBytes(c.position_m, c.velocity_m_s, c.rotation, c.principal_inertia_kg_m2,
                                c.mass_kg, c.force_N, c.torque_N_m, c.species, c.id) +
                    VectorBytes(c.member_start, c.member_slot, c.member_offset_m);
  return b;
}

}  // namespace demcal::core
