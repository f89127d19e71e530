#include "experiments/discharge/outflow_recorder.h"

#include "experiments/discharge/sphere_mass_share.h"

namespace demcal::objectives {

OutflowRecorder::OutflowRecorder(size_t species_count, double plane_z_m)
    : plane_z_m_(plane_z_m), cumulative_kg_(species_count, 0.0) {}

void OutflowRecorder::Sample(const core::Simulation& sim) {
  const core::Particles& p = sim.particles();
  const std::vector<double> mass = SphereMassShares(p);  // a clump counts once, not per member
  remaining_count_ = 0;
  remaining_kg_ = 0;
  for (size_t i = 0; i < p.Size(); ++i) {
    if (p.inv_mass[i] == 0 && p.body[i] < 0) continue;  // fixed spheres never flow
    if (p.position_m[i].z >= plane_z_m_) {
      ++remaining_count_;
      remaining_kg_ += mass[i];
      continue;
    }
    const size_t id = static_cast<size_t>(p.id[i]);
    if (id >= counted_.size()) counted_.resize(id + 1, 0);
    if (counted_[id]) continue;
    counted_[id] = 1;
    cumulative_kg_[p.species[i]] += mass[i];
    total_out_kg_ += mass[i];
  }
  samples_.push_back({sim.time_s(), cumulative_kg_});
}

}  // namespace demcal::objectives
