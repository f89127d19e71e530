// Wall loads (DEM core II, geometry): the force and torque particles exert on each wall. In a
// settled bed the walls together carry the bed's weight (static equilibrium, Newton's third
// law); the sum is deterministic for any thread count.
#include <catch2/catch.hpp>
#include <cmath>

#include "core/walls/wall_test_support.h"

using namespace demcal::core;
using namespace demcal::core::wall_test;

namespace {

// 300 spheres of 2 mm poured into a 24 × 24 mm box (planes or a mesh) and settled.
Scene BedScene(const std::vector<Wall>& walls) {
  Scene s = OneMaterialScene(0.002, /*friction=*/0.5, /*restitution=*/0.3);
  s.materials[0].youngs_modulus_Pa = 1e7;
  s.time.timestep_s = 0;  // 0.2 × Rayleigh time
  s.walls = walls;
  s.fills.push_back({0, {0.001, 0.001, 0.002}, {0.023, 0.023, 0.04}, 300, {0, 0, -0.2}});
  s.domain_min_m = {0, 0, 0};
  s.domain_max_m = {0.024, 0.024, 0.06};
  return s;
}

}  // namespace

TEST_CASE("the walls under a settled bed carry its weight", "[physics]") {
  const Vec3 lo{0, 0, 0}, hi{0.024, 0.024, 0.06};
  std::vector<Wall> walls;
  SECTION("plane box") { walls = BoxInnerFaces("box", lo, hi, 0, /*open_top=*/true); }
  SECTION("mesh box") { walls = {MeshBox("box", lo, hi, /*open_top=*/true)}; }
  const Scene s = BedScene(walls);
  Simulation sim(s, {.threads = 2});
  InitializeOrFail(sim);
  REQUIRE(sim.Run(0.5).ok());
  const double weight = 300 * SphereMass(s, 0.001) * 9.81;
  const std::vector<WallLoad> loads = sim.WallLoads();
  const Vec3 total = TotalWallForce(sim);
  INFO("sum of wall forces / weight: " << -total.z / weight << " (floor alone "
       << -loads[walls.size() == 1 ? 0 : 4].force_N.z / weight << "), horizontal "
       << std::hypot(total.x, total.y) / weight << ", KE " << sim.KineticEnergy() << " J");
  CHECK(sim.KineticEnergy() < 1e-8);
  CHECK(-total.z == Approx(weight).epsilon(0.01));
  CHECK(std::hypot(total.x, total.y) < 0.01 * weight);
}

TEST_CASE("moving cylinder, cone and mesh walls give the same results for any thread count",
          "[unit]") {
  // Spheres fall into a funnel (cone) around a rising post (outside of a cylinder) onto a mesh
  // plate that slides sideways, in a box of planes.
  Scene s = BedScene(BoxInnerFaces("box", {0, 0, 0}, {0.024, 0.024, 0.06}, 0, true));
  s.fills = {{0, {0.001, 0.001, 0.03}, {0.0075, 0.023, 0.058}, 75, {}},
             {0, {0.0165, 0.001, 0.03}, {0.023, 0.023, 0.058}, 75, {}}};
  Wall post("post", 0, CylinderSurface{.axis_point_m = {0.012, 0.012, 0}, .radius_m = 0.003,
                                       .inside = false});
  post.velocity_m_s = {0, 0, 0.05};
  post.motion_start_s = 0.05;
  s.walls.push_back(post);
  s.walls.push_back(Wall("funnel", 0, ConeFrustumSurface{.axis_point_m = {0.012, 0.012, 0},
                                                         .height0_m = 0.01, .radius0_m = 0.006,
                                                         .height1_m = 0.025, .radius1_m = 0.02}));
  Wall plate = MeshPlate("plate", 0.005, 0);
  std::get<MeshRef>(plate.shape).offset_m = {0.012, 0.012, 0.004};
  plate.velocity_m_s = {0.05, 0, 0};
  plate.motion_start_s = 0.1;
  plate.load_point_m = {0.012, 0.012, 0.004};
  s.walls.push_back(plate);

  auto run = [&](int threads) {
    Simulation sim(s, {.threads = threads});
    InitializeOrFail(sim);
    const RunSummary summary = sim.Run(0.2);
    INFO(summary.message);
    REQUIRE(summary.ok());
    return std::make_pair(sim.particles().position_m, sim.WallLoads());
  };
  const auto [x1, loads1] = run(1);
  for (int threads : {2, 3}) {
    const auto [x, loads] = run(threads);
    CHECK(x == x1);
    REQUIRE(loads.size() == loads1.size());
    for (size_t w = 0; w < loads.size(); ++w) {
      CHECK(loads[w].force_N == loads1[w].force_N);
      CHECK(loads[w].torque_N_m == loads1[w].torque_N_m);
    }
  }
  for (size_t w = 5; w < 8; ++w) {
    INFO("wall " << w);
    CHECK(Norm(loads1[w].force_N) > 0);  // post, funnel and plate are all touched
  }
  CHECK(loads1[7].point_m.x == Approx(0.012 + 0.05 * 0.1).margin(1e-6));
}
