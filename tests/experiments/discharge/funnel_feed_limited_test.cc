// objectives::FeedLimited: a funnel that empties within one free fall through its height
// (sqrt(2 h / g)) of its feed's length passed the feed as it came; its time measures the feed.
#include <catch2/catch.hpp>
#include <cmath>
#include <string>

#include "experiments/discharge/funnel_clock.h"

using demcal::objectives::FeedLimited;
using demcal::objectives::FunnelRegime;

TEST_CASE("feed-limited funnel: emptying within one free fall of the feed's length", "[unit]") {
  // h = 0.04 m, g = 9.81: sqrt(2 · 0.04 / 9.81) = 0.0903 s.
  const double fall = std::sqrt(2 * 0.04 / 9.81);
  CHECK(FeedLimited(1.54 + 0.07, 1.54, 0.04, 9.81));          // demcal's s = 2 heap: 1.61 s
  CHECK(FeedLimited(1.54 + fall - 1e-6, 1.54, 0.04, 9.81));
  CHECK_FALSE(FeedLimited(1.54 + fall + 1e-6, 1.54, 0.04, 9.81));
  CHECK_FALSE(FeedLimited(2.22, 1.54, 0.04, 9.81));           // held a charge for 0.68 s
  CHECK_FALSE(FeedLimited(0.0, 1.54, 0.04, 9.81));            // never emptied: no verdict
  CHECK_FALSE(FeedLimited(1.6, 1.54, 0.04, 0.0));             // no gravity: no free fall
}

TEST_CASE("funnel regime: orifice-limited when the funnel drains after the feed", "[unit]") {
  // h = 0.06 m: sqrt(2 · 0.06 / 9.81) = 0.111 s.
  CHECK(std::string(FunnelRegime(true, 2.2, 1.54, 0.06, 9.81)) == "orifice_limited");
  CHECK(std::string(FunnelRegime(true, 1.6, 1.54, 0.06, 9.81)) == "feed_limited");
  CHECK(std::string(FunnelRegime(false, 0.0, 1.54, 0.06, 9.81)) == "not_emptied");
}
