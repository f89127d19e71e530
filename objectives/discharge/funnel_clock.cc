#include "objectives/discharge/funnel_clock.h"

namespace demcal::objectives {

void FunnelClock::Observe(const core::Simulation& sim) {
  const core::Particles& p = sim.particles();
  int64_t above = 0;
  bool below = false;
  for (size_t i = 0; i < p.Size(); ++i) {
    if (p.inv_mass[i] == 0 && p.body[i] < 0) continue;  // glued
    if (p.position_m[i].z >= orifice_z_m_)
      ++above;
    else
      below = true;
  }
  spheres_above_ = above;
  const double t = sim.time_s();
  if (below && !started()) first_out_s_ = t;
  if (started() && !emptied() && above == 0 && t >= feed_end_s_) empty_s_ = t;
}

}  // namespace demcal::objectives
