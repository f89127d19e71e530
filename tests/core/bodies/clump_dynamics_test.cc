// Clumped spheres inside the engine: a one-sphere clump is a sphere; clumps pour and settle;
// a clump's members never interact with each other.
#include <catch2/catch.hpp>

#include <cmath>

#include "core/simulation/simulation.h"

using namespace demcal::core;

namespace {

// A sphere (or a one-sphere clump) thrown spinning onto a rough floor: sliding, rolling with
// EPSD resistance and bouncing all exercise contact force and torque.
Scene ThrownOnFloor(bool as_clump) {
  Scene s;
  s.materials = {{"m", 1e7, 0.25, 2000}};
  s.species = {{"a", 0, {}, {}}};
  s.species[0].size.diameter_m = 0.004;
  if (as_clump) s.species[0].clump_shape = {{{0, 0, 0}, 1.0}};
  PairParameters pair;
  pair.sliding_friction = 0.4;
  pair.rolling_friction = 0.05;
  pair.restitution = 0.6;
  s.pair_parameters = {pair};
  s.rolling.name = "epsd";
  s.walls = {PlaneWall{"floor", {0, 0, 0}, {0, 0, 1}, 0, {}}};
  s.domain_min_m = {-1, -1, -0.01};
  s.domain_max_m = {1, 1, 0.2};
  s.particles = {{0, {0, 0, 0.01}, {0.3, 0.1, -0.2}, {5, -20, 3}, 0, {}}};
  s.time.duration_s = 0.3;
  return s;
}

}  // namespace

TEST_CASE("a one-sphere clump moves like the sphere", "[unit][clump]") {
  Simulation sphere(ThrownOnFloor(false), {.threads = 1});
  Simulation clump(ThrownOnFloor(true), {.threads = 1});
  std::string err;
  REQUIRE(sphere.Initialize(&err));
  REQUIRE(clump.Initialize(&err));
  REQUIRE(clump.system().clumps.Size() == 1);
  // Same mass and inertia (docs/physics.md §7.1: a single sphere's exact properties).
  const double m = sphere.particles().mass_kg[0];
  CHECK(clump.system().clumps.mass_kg[0] == Approx(m).epsilon(1e-12));
  CHECK(clump.system().clumps.principal_inertia_kg_m2[0].x ==
        Approx(1.0 / sphere.particles().inv_inertia[0]).epsilon(1e-12));
  for (int chunk = 0; chunk < 30; ++chunk) {
    REQUIRE(sphere.Run(0.01).ok());
    REQUIRE(clump.Run(0.01).ok());
    const Vec3 dx = sphere.particles().position_m[0] - clump.particles().position_m[0];
    const Vec3 dw = sphere.particles().angular_velocity_rad_s[0] -
                    clump.particles().angular_velocity_rad_s[0];
    // Rounding differs (L = Iω and the quaternion drift), so agreement is to round-off growth.
    CHECK(Norm(dx) < 1e-9);
    CHECK(Norm(dw) < 1e-6 * (1 + Norm(sphere.particles().angular_velocity_rad_s[0])));
  }
}

TEST_CASE("three-sphere clumps pour into a box and settle without members interacting",
          "[physics][clump]") {
  Scene s;
  s.materials = {{"m", 5e6, 0.25, 1000}};
  s.species = {{"rods", 0, {}, {{{-1, 0, 0}, 0.8}, {{0, 0, 0}, 0.8}, {{1, 0, 0}, 0.8}}}};
  s.species[0].size.diameter_m = 0.004;
  PairParameters pair;
  pair.sliding_friction = 0.5;
  pair.rolling_friction = 0.05;
  s.pair_parameters = {pair};
  s.walls = BoxInnerFaces("box", {0, 0, 0}, {0.04, 0.04, 0.12}, 0, true);
  s.domain_min_m = {0, 0, 0};
  s.domain_max_m = {0.04, 0.04, 0.12};
  s.fills = {{0, {0.002, 0.002, 0.01}, {0.038, 0.038, 0.11}, 200, {0, 0, -0.3}}};
  Simulation sim(s, {.threads = 2});
  std::string err;
  REQUIRE(sim.Initialize(&err));
  REQUIRE(sim.system().clumps.Size() == 200);
  REQUIRE(sim.particles().Size() == 600);
  // Overlapping members of one clump are never listed as a contact pair.
  for (size_t i = 0; i < sim.particles().Size(); ++i)
    for (uint32_t k = sim.neighbours().RowBegin(i); k < sim.neighbours().RowEnd(i); ++k)
      CHECK(sim.particles().body[i] != sim.particles().body[sim.neighbours().Partner(k)]);
  const RunSummary r = sim.Run(0.6);
  REQUIRE(r.ok());
  // Settled: kinetic energy tiny compared with the potential energy lost, and nothing below
  // the floor.
  const double mass = sim.system().clumps.mass_kg[0] * 200;
  CHECK(sim.KineticEnergy() < 1e-3 * mass * 9.81 * 0.05);
  for (const Vec3& x : sim.particles().position_m) CHECK(x.z > 0);
  // The spatial re-sorts kept each clump's members in consecutive slots (member order) and
  // numbered the clumps by slot (ParticleSystem::GroupClumpMembers, Permute), with every member
  // still where its clump puts it.
  REQUIRE(r.neighbour_rebuilds > 20);  // at least one re-sort (every 20 rebuilds)
  const Clumps& c = sim.system().clumps;
  for (size_t k = 0; k < c.Size(); ++k) {
    const uint32_t first = c.member_slot[c.member_start[k]];
    CHECK(first == 3 * k);
    for (uint32_t m = c.member_start[k]; m < c.member_start[k + 1]; ++m) {
      const uint32_t slot = c.member_slot[m];
      CHECK(slot == first + (m - c.member_start[k]));
      CHECK(sim.particles().body[slot] == static_cast<int>(k));
      const Vec3 expected = c.position_m[k] + Rotate(c.rotation[k].orientation, c.member_offset_m[m]);
      CHECK(Norm(sim.particles().position_m[slot] - expected) < 1e-12);
    }
  }
}
