#pragma once
// The expected end of a settling run, for progress lines. Until the pour ends a run's length is
// the pour plus a short settle; after it the run lasts until the specific kinetic energy falls to
// the threshold (or the surface stops moving, or max_time_s). A heap that drains a metering
// funnel keeps moving for seconds after the feed ends, so a fixed guess leaves the display at
// "99 %, ETA 5 s" for most of the run. The estimate follows the energy instead: the energy
// decays at rate k = −d ln E / dt, so it reaches the threshold after ln(E / E_threshold) / k.
// While the energy does not decay (grains still pouring through the orifice) nothing better
// than max_time_s is known, and the estimate says so.
//
// k is the least-squares slope of ln E over the last kSpanS of checks, not the difference of two
// checks: the energy of a draining heap rattles by tens of per cent from one check to the next,
// and one steep-looking pair would put the end seconds early. The progress line never lets its
// fraction fall back (replicate_progress.h), so an early end shown once holds the percentage
// while the ETA grows for the rest of the run; a late one only delays the percentage.
#include <algorithm>
#include <cmath>
#include <deque>
#include <utility>

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
    samples_.emplace_back(t, std::log(e));
    while (t - samples_.front().first > kSpanS) samples_.pop_front();
    if (updated_at_s_ < 0) {
      updated_at_s_ = t;
      estimate_s_ = max_time_s_;
    } else if (t - updated_at_s_ >= kUpdateS && t - samples_.front().first >= kUpdateS) {
      const double rate = -LogEnergySlope();  // 1/s, > 0 when decaying
      estimate_s_ = rate > 0 && e > threshold_ ? t + std::log(e / threshold_) / rate
                    : rate > 0                 ? t
                                               : max_time_s_;
      updated_at_s_ = t;
    }
    return Clamp(estimate_s_, t);
  }

 private:
  // 0.1 s between updates: the surface criterion's window (settled_run.h), long enough to
  // average over the collisions of a rattling heap. 0.5 s of history for the slope: five such
  // windows. For uncorrelated scatter σ in ln E, least squares over n equally spaced checks
  // spanning T has a slope error σ·√(12/n)/T: at the default 0.01 s checks about 1.0 σ per
  // second, against 14 σ for the difference of two checks 0.1 s apart. The span is still short
  // against the seconds a drain or a settle lasts; when the decay starts the slope lags by up
  // to the span, so the end shows late, not early.
  static constexpr double kUpdateS = 0.1;
  static constexpr double kSpanS = 0.5;

  double LogEnergySlope() const {
    double mt = 0, my = 0;
    for (const auto& [t, y] : samples_) mt += t, my += y;
    mt /= samples_.size();
    my /= samples_.size();
    double stt = 0, sty = 0;
    for (const auto& [t, y] : samples_) stt += (t - mt) * (t - mt), sty += (t - mt) * (y - my);
    return stt > 0 ? sty / stt : 0;
  }
  double Clamp(double end_s, double t) const { return std::clamp(end_s, t, std::max(t, max_time_s_)); }

  double pour_end_s_, guess_s_, threshold_, max_time_s_;
  std::deque<std::pair<double, double>> samples_;  // (t in s, ln E) of the checks after the pour
  double updated_at_s_ = -1;
  double estimate_s_ = 0;
};

}  // namespace demcal::objectives
