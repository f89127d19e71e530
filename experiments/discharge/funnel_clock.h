#pragma once
// FunnelClock: times the discharge of a funnel (or a feeder) from the particle states seen at
// regular checks of a run: the first moment a grain is below the orifice, and the first moment
// after the feed has ended with no grain left at or above the orifice height (the funnel is
// empty). Fixed (glued) spheres are ignored. The resolution is the check interval.
//
// Usage (from a run's per-check hook):
//   FunnelClock clock(orifice_z, feed_end_s);
//   hooks.on_check = [&](const core::Simulation& sim) { clock.Observe(sim); };
//   if (clock.emptied()) use(clock.DischargeTimeS());
#include <cstdint>

#include "core/simulation/simulation.h"

namespace demcal::objectives {

// True when a funnel that emptied did so within one free fall through its own height
// (sqrt(2 h / g)) of the feed's own length: it passed the feed as it came and never held grains
// back, so its discharge time measures the feed rate, not the powder's flow through the orifice.
// The free-fall time is the time scale of a grain's passage through the funnel; a funnel that
// holds a charge adds the time to drain it, which a flowability change lengthens.
bool FeedLimited(double discharge_time_s, double feed_duration_s, double funnel_height_m,
                 double gravity_m_s2);

// What set a funnel's discharge time: "feed_limited" (FeedLimited), "orifice_limited" (it
// emptied later than that: it held a charge after the feed ended, which only the orifice drains,
// so its time measures the powder's flow) or "not_emptied".
const char* FunnelRegime(bool emptied, double discharge_time_s, double feed_duration_s,
                         double funnel_height_m, double gravity_m_s2);

class FunnelClock {
 public:
  FunnelClock(double orifice_z_m, double feed_end_s)
      : orifice_z_m_(orifice_z_m), feed_end_s_(feed_end_s) {}

  void Observe(const core::Simulation& sim);

  bool started() const { return first_out_s_ >= 0; }
  bool emptied() const { return empty_s_ >= 0; }
  double first_out_s() const { return first_out_s_; }
  double empty_s() const { return empty_s_; }
  // empty − first out; 0 unless emptied().
  double DischargeTimeS() const { return emptied() ? empty_s_ - first_out_s_ : 0; }
  // Spheres (clump members counted singly) at or above the orifice at the last check.
  int64_t spheres_above() const { return spheres_above_; }

 private:
  double orifice_z_m_;
  double feed_end_s_;
  double first_out_s_ = -1;
  double empty_s_ = -1;
  int64_t spheres_above_ = 0;
};

}  // namespace demcal::objectives
