// Insertion regions that are not static boxes: cylinder fills (a silo) and factory regions that
// move with a velocity or follow the heap they feed (core/insertion/factory.h), so that a staged pour is
// one scene.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "core/simulation/simulation.h"

using namespace demcal::core;

namespace {

Scene Bin() {
  Scene s;
  s.materials = {{"m", 5e6, 0.25, 2500}};
  s.species = {{"grain", 0, {}}};
  s.species[0].size.diameter_m = 0.002;
  PairParameters pair;
  pair.sliding_friction = 0.5;
  pair.rolling_friction = 0.2;
  pair.restitution = 0.3;
  s.pair_parameters = {pair};
  s.rolling.name = "epsd";
  s.walls = BoxInnerFaces("bin", {0, 0, 0}, {0.04, 0.04, 0.2}, 0, true);
  s.domain_min_m = {0, 0, 0};
  s.domain_max_m = {0.04, 0.04, 0.2};
  s.seed = 3;
  return s;
}

FactorySpec Feed() {
  FactorySpec f;
  f.name = "feed";
  f.region = InsertionRegion::Cylinder({0.02, 0.02, 0}, 0.006, 0.04, 0.05);
  f.species = {0};
  f.mass_fractions = {1};
  f.mass_rate_kg_s = 0.01;
  return f;
}

}  // namespace

TEST_CASE("a cylinder fill places every particle inside the cylinder", "[unit][factory]") {
  Scene s = Bin();
  s.fills = {{0, InsertionRegion::Cylinder({0.02, 0.02, 0}, 0.012, 0.01, 0.05), 300}};
  Simulation sim(s, {.threads = 1});
  std::string err;
  REQUIRE(sim.Initialize(&err));
  const Particles& p = sim.particles();
  REQUIRE(p.Size() == 300);
  double r_max = 0;
  for (size_t i = 0; i < p.Size(); ++i) {
    const Vec3 d = p.position_m[i] - Vec3{0.02, 0.02, 0};
    r_max = std::max(r_max, std::hypot(d.x, d.y) + p.radius_m[i]);
    CHECK(p.position_m[i].z - p.radius_m[i] >= 0.01);
    CHECK(p.position_m[i].z + p.radius_m[i] <= 0.05);
  }
  CHECK(r_max <= 0.012);
  CHECK(r_max > 0.011);  // it fills the whole cross-section, not just a box inside it
}

TEST_CASE("a factory region moves with its velocity while active", "[unit][factory]") {
  Scene s = Bin();
  FactorySpec f = Feed();
  f.region_velocity_m_s = {0.05, 0, 0.1};
  f.start_s = 0.01;
  f.end_s = 0.21;
  f.batch_interval_s = 0.005;  // the newest grains have fallen < 0.2 mm
  s.factories = {f};
  Simulation sim(s, {.threads = 1});
  std::string err;
  REQUIRE(sim.Initialize(&err));
  REQUIRE(sim.Run(0.12).ok());
  // The newest grain was placed in the region as it was at its batch (t >= 0.115 s: shifted
  // by >= 10.5 mm up, above where the region started, z in [0.04, 0.05]).
  const Particles& p = sim.particles();
  int64_t newest = -1;
  size_t slot = 0;
  for (size_t i = 0; i < p.Size(); ++i)
    if (p.id[i] > newest) newest = p.id[i], slot = i;
  REQUIRE(newest >= 0);
  CHECK(p.position_m[slot].z > 0.05);
  SizeDistribution size;
  size.diameter_m = 0.002;
  ParticleFactory probe(f, {{0, 0, 2500, &size, 1}}, 9.81, 1);
  const InsertionRegion at_end = probe.RegionAt(1.0);  // stops at end_s
  CHECK(at_end.min_m.x == Approx(0.014 + 0.05 * 0.2));
  CHECK(at_end.max_m.z == Approx(0.05 + 0.1 * 0.2));
  CHECK(probe.RegionAt(0).min_m.z == Approx(0.04));  // not before start_s
}

TEST_CASE("a factory following the heap keeps its clearance above the heap top",
          "[unit][factory]") {
  Scene s = Bin();
  FactorySpec f = Feed();
  f.region = InsertionRegion::Cylinder({0.02, 0.02, 0}, 0.005, 0.012, 0.02);
  f.mass_rate_kg_s = 0.02;
  f.velocity_m_s = {0, 0, -0.5};  // batches every 17 ms: 22 % solid fraction in the region
  f.follow_heap_clearance_m = 0.008;
  s.factories = {f};
  Simulation sim(s, {.threads = 1});
  std::string err;
  REQUIRE(sim.Initialize(&err));
  const RunSummary r = sim.Run(0.6);
  INFO(r.BriefReport());
  REQUIRE(r.ok());
  const FactoryReport report = sim.FactoryReports()[0];
  // The heap under the stream: the highest grain within the stream's footprint.
  const Particles& p = sim.particles();
  double top = 0;
  for (size_t i = 0; i < p.Size(); ++i) {
    const Vec3& x = p.position_m[i];
    if (std::abs(x.x - 0.02) < 0.005 && std::abs(x.y - 0.02) < 0.005 && p.velocity_m_s[i].z > -0.05 &&
        x.z < 0.012 + report.region_lift_m - 0.004)
      top = std::max(top, x.z + p.radius_m[i]);
  }
  INFO("lift " << report.region_lift_m << " m, heap top " << top << " m");
  CHECK(report.region_lift_m > 0.004);  // the heap grew above the initial clearance
  // The region's bottom is about the clearance above the heap top (within a grain or two).
  CHECK(std::abs(0.012 + report.region_lift_m - (top + 0.008)) < 0.004);
}

TEST_CASE("a few grains filled into a region 200 km wide are placed and run",
          "[unit][factory][bad_inputs]") {
  // One cell per grain diameter over the region would be 1e23 cells; the fill's occupancy grid
  // and the neighbour grid both cap their cells per particle (insertion.cc, neighbour_list.h).
  Scene s = Bin();
  s.walls.clear();
  s.gravity_m_s2 = {0, 0, 0};
  s.domain_min_m = {-1e5, -1e5, -1e5};
  s.domain_max_m = {1e5, 1e5, 1e5};
  s.fills = {{0, InsertionRegion::Box({-9.9e4, -9.9e4, -9.9e4}, {9.9e4, 9.9e4, 9.9e4}), 20}};
  Simulation sim(s, {.threads = 1});
  std::string err;
  REQUIRE(sim.Initialize(&err));
  REQUIRE(sim.particles().Size() == 20);
  const RunSummary run = sim.Run(100 * sim.timestep_s());
  CHECK(run.ok());
  CHECK(sim.Heap().Total() < (size_t{64} << 20));  // a few MB: cells in proportion
  CHECK(sim.particles().Size() == 20);
}
