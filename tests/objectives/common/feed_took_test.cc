// How long a feed took (objectives/common/feed.h): mass / rate while its factory keeps up; the
// time it had inserted its whole mass when the factory could not insert that fast (large clumps
// placed at random in the feed region), so that a funnel's regime is judged against the pour it
// actually got.
#include <catch2/catch.hpp>

#include "core/simulation/simulation.h"
#include "objectives/common/feed.h"

using namespace demcal;
using namespace demcal::objectives;

TEST_CASE("a feed that kept up took mass / rate; one that fell behind took longer", "[unit]") {
  Feed feed;
  feed.components = {{0, 1.0}};
  feed.mass_kg = 0.01;
  feed.mass_rate_kg_s = 0.1;  // nominal pour 0.1 s
  feed.start_s = 0.2;
  CHECK(FeedTookS(feed, -1, 0.002) == Approx(0.1));      // never seen complete: nominal
  CHECK(FeedTookS(feed, 0.301, 0.002) == Approx(0.1));   // at its end, within a check
  CHECK(FeedTookS(feed, 0.45, 0.002) == Approx(0.25));   // fell behind: 0.45 − 0.2
}

TEST_CASE("FeedInserted follows the feed factory's inserted mass", "[unit]") {
  // 4 mm grains, 10 of them at 25 grains' mass per second from 0.1 s: not inserted before the
  // pour, inserted once it has run (a factory that falls behind is the case of docs/
  // experiments/segregation_angle.md's clump feeds, too slow to reproduce in a unit test).
  core::Scene s;
  s.materials = {{"m", 1e7, 0.25, 2000}};
  s.species = {{"grain", 0, {}, {}}};
  s.species[0].size.diameter_m = 0.004;
  s.pair_parameters = {core::PairParameters{}};
  s.gravity_m_s2 = {0, 0, -9.81};
  s.domain_min_m = {-0.05, -0.05, -2};
  s.domain_max_m = {0.05, 0.05, 0.1};
  s.time.duration_s = 1;
  const double grain_kg = 2000 * 3.14159265358979 / 6 * 0.004 * 0.004 * 0.004;
  Feed feed;
  feed.components = {{0, 1.0}};
  feed.mass_kg = 10 * grain_kg;
  feed.mass_rate_kg_s = 25 * grain_kg;  // nominal pour 0.4 s
  feed.start_s = 0.1;
  const auto region = core::InsertionRegion::Box({-0.02, -0.02, 0.0}, {0.02, 0.02, 0.04});
  s.factories.push_back(MakeFeedFactory(s, feed, region));
  core::Simulation sim(s, {.threads = 1});
  std::string error;
  const bool initialized = sim.Initialize(&error);
  INFO(error);
  REQUIRE(initialized);
  CHECK_FALSE(FeedInserted(sim, feed));
  REQUIRE(sim.Run(0.3).ok());
  CHECK_FALSE(FeedInserted(sim, feed));  // mid-pour
  REQUIRE(sim.Run(0.3).ok());
  CHECK(FeedInserted(sim, feed));
}
