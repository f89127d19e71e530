#include <catch2/catch.hpp>

#include "core/simulation.h"

using namespace demcal::core;

namespace {

Scene TwoSpheres(bool fix_lower) {
  Scene s;
  s.materials = {{"m", 1e7, 0.25, 1000}};
  s.species = {{"a", 0, {}}};
  s.species[0].size.diameter_m = 0.01;
  s.pair_parameters = {PairParameters{}};
  s.domain_min_m = {-1, -1, -1};
  s.domain_max_m = {1, 1, 1};
  ParticleSpec lower{0, {0, 0, 0}, {}, {}, 0};
  lower.fixed = fix_lower;
  s.particles = {lower, {0, {0.001, 0, 0.0105}, {}, {}, 0}};
  return s;
}

}  // namespace

TEST_CASE("a fixed sphere carries another without moving", "[unit]") {
  Simulation sim(TwoSpheres(true), {.threads = 1});
  std::string err;
  REQUIRE(sim.Initialize(&err));
  REQUIRE(sim.Run(0.3).ok());
  const Particles& p = sim.particles();
  const size_t lower = p.id[0] < p.id[1] ? 0 : 1;
  CHECK(p.position_m[lower].x == 0);
  CHECK(p.position_m[lower].y == 0);
  CHECK(p.position_m[lower].z == 0);
  // The upper sphere rolled off the (off-centre) fixed one and fell below it.
  CHECK(p.position_m[1 - lower].z < -0.05);
  // A fixed sphere (infinite inertia) adds no kinetic energy, and no NaN.
  const size_t upper = 1 - lower;
  CHECK(sim.KineticEnergy() == Approx(p.FreeKineticEnergy(upper)).epsilon(1e-12));
}

TEST_CASE("fixed clumps are refused with the field name", "[unit]") {
  Scene s = TwoSpheres(true);
  s.species[0].clump_shape = {{{-0.5, 0, 0}, 1.0}, {{0.5, 0, 0}, 1.0}};
  std::string err;
  CHECK_FALSE(s.IsValid(&err));
  CHECK_THAT(err, Catch::Contains("particles[0].fixed"));
}
