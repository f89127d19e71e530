#include "objectives/common/settle_eta.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>

using namespace demcal::objectives;

// An energy that decays exponentially, E(t) = E0 exp(−k (t − t0)), reaches the threshold at
// t0 + ln(E0 / E_threshold) / k exactly: the estimate must find that time from two windows.
TEST_CASE("SettleEta finds the end of an exponential decay", "[objectives][settle]") {
  const double pour_end = 1.5, k = 4.0, e0 = 1e-2, threshold = 1e-5, max_time = 20;
  const double exact = pour_end + std::log(e0 / threshold) / k;
  SettleEta eta(pour_end, pour_end + 0.3, threshold, max_time);
  double end = 0;
  for (double t = pour_end; t < pour_end + 0.35; t += 0.01)
    end = eta.ExpectedEndS(t, e0 * std::exp(-k * (t - pour_end)));
  CHECK(end == Approx(exact).epsilon(1e-9));
}

TEST_CASE("SettleEta: the guess before the pour ends, the hard stop while nothing decays",
          "[objectives][settle]") {
  SettleEta eta(1.5, 1.8, 1e-5, 6);
  CHECK(eta.ExpectedEndS(0.2, NAN) == Approx(1.8));
  CHECK(eta.ExpectedEndS(1.9, NAN) == Approx(1.9));  // past the guess: never before now
  // Grains still draining through an orifice: the energy holds, so only max_time_s is known.
  for (double t = 1.5; t < 2.0; t += 0.01) eta.ExpectedEndS(t, 0.05);
  CHECK(eta.ExpectedEndS(2.0, 0.05) == Approx(6));
  // A rising energy (an avalanche) is no decay either.
  for (double t = 2.0; t < 2.3; t += 0.01) eta.ExpectedEndS(t, 0.05 * (1 + t));
  CHECK(eta.ExpectedEndS(2.3, 0.2) == Approx(6));
}

TEST_CASE("SettleEta stays within [now, max_time]", "[objectives][settle]") {
  SettleEta eta(0.0, 0.3, 1e-5, 2.0);
  // A very slow decay would end long after the hard stop: the stop bounds it.
  for (double t = 0; t < 0.5; t += 0.01) {
    const double end = eta.ExpectedEndS(t, 1e-2 * std::exp(-0.01 * t));
    CHECK(end >= t);
    CHECK(end <= 2.0);
  }
  // Below the threshold already (the surface rule is still running): the end is now.
  SettleEta below(0.0, 0.3, 1e-5, 2.0);
  below.ExpectedEndS(0.0, 2e-6);
  CHECK(below.ExpectedEndS(0.1, 1e-6) == Approx(0.1));
}

// A heap fed through a funnel: the energy holds while the funnel drains, then decays. Guessing
// the hard stop from the start (segregation with a funnel), the shown fraction t / end never
// falls back; guessing the pour's end, it falls back when the pour ends.
TEST_CASE("SettleEta from the hard stop: the progress fraction only moves forward",
          "[objectives][settle]") {
  const double pour_end = 1.5, drained = 3.5, max_time = 6;
  auto energy = [&](double t) {
    return t < drained ? 0.05 : 0.05 * std::exp(-6 * (t - drained));
  };
  SettleEta from_stop(pour_end, max_time, 1e-5, max_time), from_pour(pour_end, pour_end + 0.3, 1e-5, max_time);
  double last_stop = 0, last_pour = 0;
  bool fell_back = false;
  for (double t = 0.01; t < 5; t += 0.01) {
    const double e = t < pour_end ? NAN : energy(t);
    const double f_stop = t / from_stop.ExpectedEndS(t, e), f_pour = t / from_pour.ExpectedEndS(t, e);
    CHECK(f_stop >= last_stop - 1e-12);
    fell_back = fell_back || f_pour < last_pour - 0.2;
    last_stop = f_stop;
    last_pour = f_pour;
  }
  CHECK(fell_back);
}

// A funnel draining into the heap: the energy rattles by ±30 % about a plateau, then decays. The
// progress line holds the largest fraction it has shown (replicate_progress.h), so an end shown
// too early once stays on the screen: the fraction t / end must never run ahead of the true one.
TEST_CASE("SettleEta: a rattling plateau does not show an early end", "[objectives][settle]") {
  const double pour_end = 1.5, drained = 3.5, k = 6, e0 = 0.05, threshold = 1e-5, max_time = 8;
  const double true_end = drained + std::log(e0 / threshold) / k;
  uint32_t state = 12345;  // a fixed linear congruential sequence: the scatter of every check
  auto rattle = [&] {
    state = state * 1664525u + 1013904223u;
    return 0.3 * (2.0 * (state >> 8) / double(1u << 24) - 1.0);
  };
  SettleEta eta(pour_end, max_time, threshold, max_time);
  double ahead = 0;
  for (double t = pour_end; t < true_end; t += 0.01) {
    const double e = (t < drained ? e0 : e0 * std::exp(-k * (t - drained))) * std::exp(rattle());
    ahead = std::max(ahead, t / eta.ExpectedEndS(t, e) - t / true_end);
  }
  CHECK(ahead < 0.05);
}
