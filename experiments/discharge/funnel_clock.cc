#include "experiments/discharge/funnel_clock.h"

#include <cmath>

namespace demcal::objectives {

bool FeedLimited(double discharge_time_s, double feed_duration_s, double funnel_height_m,
                 double gravity_m_s2) {
  if (!(discharge_time_s > 0) || !(gravity_m_s2 > 0)) return false;
  return discharge_time_s - feed_duration_s < std::sqrt(2 * funnel_height_m / gravity_m_s2);
}

const char* FunnelRegime(bool emptied, double discharge_time_s, double feed_duration_s,
                         double funnel_height_m, double gravity_m_s2) {
  if (!emptied) return "not_emptied";
  return FeedLimited(discharge_time_s, feed_duration_s, funnel_height_m, gravity_m_s2)
             ? "feed_limited"
             : "orifice_limited";
}

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
