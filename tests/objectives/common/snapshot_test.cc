#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

#include "core/simulation/simulation.h"
#include "objectives/common/snapshot.h"

using namespace demcal;
using namespace demcal::objectives;

TEST_CASE("a snapshot holds one grain per sphere or clump, ordered by id", "[unit]") {
  core::Scene s;
  s.materials = {{"m", 1e7, 0.25, 1000}};
  s.species = {{"ball", 0, {}}, {"pair", 0, {}}};
  s.species[0].size.diameter_m = 0.01;
  s.species[1].size.diameter_m = 0.01;
  s.species[1].clump_shape = {{{-0.5, 0, 0}, 1.0}, {{0.5, 0, 0}, 1.0}};
  s.pair_parameters = std::vector<core::PairParameters>(1);
  s.domain_min_m = {-1, -1, -1};
  s.domain_max_m = {1, 1, 1};
  s.particles = {{1, {0.2, 0, 0}, {}, {}, 0}, {0, {0, 0, 0}, {}, {}, 0}};
  core::Simulation sim(s, {.threads = 1});
  std::string err;
  REQUIRE(sim.Initialize(&err));
  const Snapshot snap = TakeSnapshot(sim);
  REQUIRE(snap.grains.size() == 2);
  REQUIRE(snap.spheres.size() == 3);
  CHECK(snap.grains[0].id < snap.grains[1].id);
  int clump_members = 0;
  for (const SurfaceSphere& sphere : snap.spheres)
    clump_members += snap.grains[sphere.grain].species == 1;
  CHECK(clump_members == 2);
  for (const Grain& g : snap.grains) {
    // The volume-equivalent diameter of both species is 10 mm by construction.
    CHECK(g.radius_m == Approx(0.005).epsilon(1e-9));
    CHECK(g.mass_kg == Approx(1000 * std::numbers::pi / 6 * 1e-6).epsilon(1e-9));
  }
  const Snapshot cropped = Crop(snap, {0.1, -1, -1}, {1, 1, 1});
  REQUIRE(cropped.grains.size() == 1);
  CHECK(cropped.grains[0].species == 1);
  CHECK(cropped.spheres.size() == 2);
  CHECK(cropped.spheres[0].grain == 0);
}
