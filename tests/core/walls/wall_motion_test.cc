// Moving walls (DEM core II, geometry): a wall translates with its prescribed velocity between
// motion_start_s and motion_end_s, and its contacts see the relative velocity.
#include <catch2/catch.hpp>
#include <cmath>

#include "core/walls/wall_test_support.h"

using namespace demcal::core;
using namespace demcal::core::wall_test;

TEST_CASE("a lifted cylinder moves and drags a sphere it touches to 2/7 of its speed",
          "[physics]") {
  // A sphere at rest, pressed by a body force against the inside of a vertical cylinder lifted
  // at speed V, is a sphere on a belt: friction accelerates and spins it until its contact point
  // moves with the wall, which happens at v = (2/7) V and ω R = (5/7) V (m Δv = J, I Δω = R J,
  // I = (2/5) m R²; e.g. Kleppner & Kolenkow, An Introduction to Mechanics, rolling problems).
  // When the wall stops the same impulse balance brings the sphere back to rest.
  constexpr double kRadius = 0.002, kV = 0.01, kStop = 0.05;
  Scene s = OneMaterialScene(2 * kRadius);
  s.gravity_m_s2 = {2, 0, 0};  // presses the sphere against the wall at +x, no vertical load
  const double delta = HertzRestOverlap(s, kRadius, SphereMass(s, kRadius) * 2);
  Wall silo("silo", 0, CylinderSurface{.radius_m = 0.02, .axial_min_m = -0.05,
                                       .axial_max_m = 0.05});
  silo.velocity_m_s = {0, 0, kV};
  silo.motion_end_s = kStop;
  s.walls = {silo};
  s.particles = {{0, {0.02 - kRadius + delta, 0, 0}, {}, {}, 2 * kRadius, {}}};
  s.domain_min_m = {-0.03, -0.03, -0.03};
  s.domain_max_m = {0.03, 0.03, 0.03};
  Simulation sim(s, {.threads = 1});
  InitializeOrFail(sim);

  REQUIRE(sim.Run(0.04).ok());
  const CylinderSurface& moved = std::get<CylinderSurface>(sim.walls()[0].shape);
  CHECK(moved.axis_point_m.z == Approx(kV * sim.time_s()).epsilon(1e-12));
  CHECK(std::get<CylinderSurface>(sim.scene().walls[0].shape).axis_point_m.z == 0);
  const Vec3 v = sim.particles().velocity_m_s[0];
  const Vec3 w = sim.particles().angular_velocity_rad_s[0];
  INFO("v_z = " << v.z << " m/s (2V/7 = " << 2 * kV / 7 << "), w_y R = " << w.y * kRadius);
  CHECK(v.z == Approx(2 * kV / 7).epsilon(0.01));
  CHECK(-w.y * kRadius == Approx(5 * kV / 7).epsilon(0.01));
  CHECK(std::abs(sim.WallLoads()[0].force_N.z) < 0.01 * SphereMass(s, kRadius) * 2);

  REQUIRE(sim.Run(0.06).ok());  // the wall stopped at t = 0.05 s
  CHECK(std::get<CylinderSurface>(sim.walls()[0].shape).axis_point_m.z ==
        Approx(kV * kStop).epsilon(1e-12));
  INFO("after the stop: v_z = " << sim.particles().velocity_m_s[0].z);
  CHECK(std::abs(sim.particles().velocity_m_s[0].z) < 0.01 * kV);
}

TEST_CASE("a funnel holds spheres above a closed gate and discharges them when it opens",
          "[physics]") {
  // Cone frustum funnel (orifice radius 6 mm at z = 10 mm, 20 mm at z = 40 mm; orifice/particle
  // diameter ratio 6, above the ~5 below which orifices jam, Beverloo et al. 1961) over a plane
  // gate 1 mm below the orifice. The gate moves down from t = 0.4 s to 0.5 s; the discharged
  // spheres pile up under the funnel, which repels them as a thin shell.
  Scene s = OneMaterialScene(0.002, /*friction=*/0.3, /*restitution=*/0.3);
  s.materials[0].youngs_modulus_Pa = 1e7;
  s.time.timestep_s = 0;  // 0.2 × Rayleigh time
  s.walls.push_back(Wall("funnel", 0, ConeFrustumSurface{.height0_m = 0.01, .radius0_m = 0.006,
                                                         .height1_m = 0.04, .radius1_m = 0.02}));
  Wall gate = PlaneWall{"gate", {0, 0, 0.009}, {0, 0, 1}, 0, {0, 0, -0.4}};
  gate.motion_start_s = 0.4;
  gate.motion_end_s = 0.5;
  s.walls.push_back(gate);
  s.fills.push_back({0, {-0.006, -0.006, 0.025}, {0.006, 0.006, 0.06}, 80, {}});
  s.domain_min_m = {-0.2, -0.2, -0.05};  // discharged spheres roll away on the gate
  s.domain_max_m = {0.2, 0.2, 0.07};
  Simulation sim(s, {.threads = 2});
  InitializeOrFail(sim);
  auto count_below = [&](double z) {
    int n = 0;
    for (const Vec3& x : sim.particles().position_m) n += x.z < z;
    return n;
  };

  REQUIRE(sim.Run(0.38).ok());
  const int held_below_gate = count_below(0.009);
  const double weight = 80 * SphereMass(s, 0.001) * 9.81;
  const Vec3 on_gate = sim.WallLoads()[1].force_N, on_funnel = sim.WallLoads()[0].force_N;
  INFO("closed: below the gate " << held_below_gate << ", gate carries " << -on_gate.z / weight
       << " and funnel " << -on_funnel.z / weight << " of the weight, KE "
       << sim.KineticEnergy() << " J");
  CHECK(held_below_gate == 0);
  CHECK(sim.KineticEnergy() < 1e-7);
  CHECK((on_gate + on_funnel).z == Approx(-weight).epsilon(0.01));
  CHECK(-on_funnel.z > 0.05 * weight);  // the funnel wall carries part of the load

  const RunSummary open = sim.Run(0.35);
  INFO(open.message);
  REQUIRE(open.ok());
  const int discharged = count_below(0.0);
  INFO("discharged " << discharged << " of 80; gate at z = "
       << std::get<PlaneSurface>(sim.walls()[1].shape).point_m.z);
  CHECK(std::get<PlaneSurface>(sim.walls()[1].shape).point_m.z == Approx(0.009 - 0.04));
  CHECK(discharged >= 76);
}
