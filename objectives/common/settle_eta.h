#pragma once
// The expected end of a settling run, for progress lines. Until the pour ends a run's length is
// the pour plus a short settle; after it the run lasts until the specific kinetic energy falls to
// the threshold (or the surface stops moving, or max_time_s). A heap that drains a metering
// funnel keeps moving for seconds after the feed ends, so a fixed guess leaves the display at
// "99 %, ETA 5 s" for most of the run. The estimate follows the energy instead: over the last
// window the energy decays at rate k = −d ln E / dt, so it reaches the threshold after
// ln(E / E_threshold) / k. While the energy does not decay (grains still pouring through the
// orifice) nothing better than max_time_s is known, and the estimate says so.
#include <algorithm>
#include <cmath>

namespace demcal::objectives {

class SettleEta {
 public:
  // pour_end_s: feed end plus the minimum settle; guess_s: the end assumed until then;
  // threshold_J_kg: the kinetic-energy criterion; max_time_s: the run's hard stop.
  SettleEta(double pour_end_s, double guess_s, double threshold_J_kg, double max_time_s)
      : pour_end_s_(pour_end_s),
        guess_s_(std::min(guess_s, max_time_s)),
        threshold_(threshold_J_kg),
        max_time_s_(max_time_s) {}

  // The expected end (s, simulated) at time t with specific kinetic energy e (J/kg; NaN or ≤ 0
  // when not measured at this check). Never earlier than t, never later than max_time_s.
  double ExpectedEndS(double t, double e) {
    if (t < pour_end_s_ || !(e > 0)) return Clamp(std::max(guess_s_, estimate_s_), t);
    const double log_e = std::log(e);
    if (window_t_ < 0) {
      window_t_ = t;
      window_log_e_ = log_e;
      estimate_s_ = max_time_s_;
    } else if (t - window_t_ >= kWindowS) {
      const double rate = (window_log_e_ - log_e) / (t - window_t_);  // 1/s, > 0 when decaying
      estimate_s_ = rate > 0 && e > threshold_ ? t + std::log(e / threshold_) / rate
                    : rate > 0                 ? t
                                               : max_time_s_;
      window_t_ = t;
      window_log_e_ = log_e;
    }
    return Clamp(estimate_s_, t);
  }

 private:
  // 0.1 s: the surface criterion's window (settled_run.h), long enough to average over the
  // collisions of a rattling heap, short against the seconds a drain or a settle lasts.
  static constexpr double kWindowS = 0.1;
  double Clamp(double end_s, double t) const { return std::clamp(end_s, t, std::max(t, max_time_s_)); }

  double pour_end_s_, guess_s_, threshold_, max_time_s_;
  double window_t_ = -1, window_log_e_ = 0;
  double estimate_s_ = 0;
};

}  // namespace demcal::objectives
