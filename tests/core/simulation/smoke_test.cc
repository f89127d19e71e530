#include <catch2/catch.hpp>

#include "core/simulation/simulation.h"

using namespace demcal::core;

TEST_CASE("a sphere falls freely under gravity", "[unit]") {
  // Free fall: z(t) = z0 − g t²/2 (velocity Verlet is exact for constant acceleration).
  Scene s;
  s.materials = {{"m", 1e7, 0.25, 1000}};
  s.species = {{"a", 0, {}}};
  s.species[0].size.diameter_m = 0.01;
  s.pair_parameters = {PairParameters{}};
  s.domain_min_m = {-1, -1, -1};
  s.domain_max_m = {1, 1, 1};
  s.particles = {{0, {0, 0, 0.5}, {}, {}, 0}};
  Simulation sim(s, {.threads = 1});
  std::string err;
  REQUIRE(sim.Initialize(&err));
  const RunSummary r = sim.Run(0.1);
  REQUIRE(r.ok());
  const double t = sim.time_s();
  CHECK(sim.particles().position_m[0].z == Approx(0.5 - 0.5 * 9.81 * t * t).epsilon(1e-12));
}
