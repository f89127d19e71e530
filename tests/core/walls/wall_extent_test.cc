// WallExtent and the periodic-axis rule of Scene::IsValid: a wall in a periodic domain must stay
// a particle radius inside it along each periodic axis, or be unchanged along that axis.
#include <catch2/catch.hpp>

#include <cmath>

#include "core/walls/wall_extent.h"
#include "core/walls/wall_test_support.h"

using namespace demcal::core;

TEST_CASE("a wall's extent along an axis covers its surface and its travel", "[unit][periodic]") {
  const Wall silo("silo", 0, CylinderSurface{.axis_point_m = {0.01, 0.01, 0}, .radius_m = 0.004,
                                             .axial_min_m = 0, .axial_max_m = 0.03});
  CHECK(WallExtent(silo, 0, 1).lo_m == Approx(0.006));
  CHECK(WallExtent(silo, 0, 1).hi_m == Approx(0.014));
  CHECK(WallExtent(silo, 2, 1).lo_m == Approx(0));
  CHECK(WallExtent(silo, 2, 1).hi_m == Approx(0.03));
  // A funnel: radius 0.002 at height 0.005, 0.011 at height 0.03.
  const Wall funnel("funnel", 0, ConeFrustumSurface{.axis_point_m = {0.01, 0.01, 0},
                                                    .height0_m = 0.005, .radius0_m = 0.002,
                                                    .height1_m = 0.03, .radius1_m = 0.011});
  CHECK(WallExtent(funnel, 1, 1).lo_m == Approx(-0.001));
  CHECK(WallExtent(funnel, 1, 1).hi_m == Approx(0.021));
  // Moving at 1 m/s along x for the whole 0.01 s run: 0.01 m of travel.
  Wall moving = silo;
  moving.velocity_m_s = {1, 0, 0};
  CHECK(WallExtent(moving, 0, 0.01).hi_m == Approx(0.024));
  // Infinite and tilted: unbounded along x; infinite along x: unchanged by a shift along x.
  const Wall tilted("t", 0, CylinderSurface{.axis = {0.6, 0, 0.8}, .radius_m = 0.004});
  CHECK(std::isinf(WallExtent(tilted, 0, 1).hi_m));
  CHECK_FALSE(InvariantAlongAxis(tilted, 0));
  const Wall pipe("pipe", 0, CylinderSurface{.axis_point_m = {0, 0.01, 0.01}, .axis = {1, 0, 0},
                                             .radius_m = 0.008});
  CHECK(InvariantAlongAxis(pipe, 0));
  CHECK_FALSE(InvariantAlongAxis(pipe, 1));
  CHECK(InvariantAlongAxis(Wall(PlaneWall{"floor", {0, 0, 0}, {0, 0, 1}, 0, {}}), 0));
  CHECK_FALSE(InvariantAlongAxis(Wall(PlaneWall{"side", {0, 0, 0}, {1, 0, 0}, 0, {}}), 0));
}

TEST_CASE("walls of every shape across a periodic axis are refused", "[unit][periodic]") {
  Scene s = wall_test::OneMaterialScene(0.002);
  s.domain_min_m = {0, 0, 0};
  s.domain_max_m = {0.02, 0.02, 0.04};
  s.periodic = {true, false, false};
  s.time.duration_s = 0.01;
  std::string error;
  s.walls = {Wall("post", 0, CylinderSurface{.axis_point_m = {0.01, 0.01, 0}, .radius_m = 0.003,
                                             .axial_min_m = 0, .axial_max_m = 0.03})};
  CHECK(s.IsValid(&error));  // 0.006 m from both boundaries: repeated with the domain
  s.walls = {Wall("silo", 0, CylinderSurface{.axis_point_m = {0.01, 0.01, 0}, .radius_m = 0.0095})};
  CHECK_FALSE(s.IsValid(&error));  // 0.0005 m from the boundary: less than a radius
  CHECK_THAT(error, Catch::Contains("(cylinder 'silo') crosses the periodic axis x: it reaches "
                                    "[0.0005, 0.0195] m along x"));
  s.walls = {Wall("pipe", 0, CylinderSurface{.axis_point_m = {0, 0.01, 0.02}, .axis = {1, 0, 0},
                                             .radius_m = 0.008})};
  CHECK(s.IsValid(&error));  // infinite along the periodic axis
  s.walls = {Wall("funnel", 0, ConeFrustumSurface{.axis_point_m = {0.01, 0.01, 0},
                                                  .height0_m = 0.005, .radius0_m = 0.002,
                                                  .height1_m = 0.03, .radius1_m = 0.011})};
  CHECK_FALSE(s.IsValid(&error));
  CHECK_THAT(error, Catch::Contains("(cone 'funnel') crosses the periodic axis x"));
  s.walls = {Wall("tilted", 0, CylinderSurface{.axis_point_m = {0.01, 0.01, 0},
                                               .axis = {0.6, 0, 0.8}, .radius_m = 0.003})};
  CHECK_FALSE(s.IsValid(&error));
  CHECK_THAT(error, Catch::Contains("is unbounded along x"));
  s.walls = {wall_test::MeshBox("box", {0, 0, 0}, {0.02, 0.02, 0.04}, true)};
  CHECK_FALSE(s.IsValid(&error));
  CHECK_THAT(error, Catch::Contains("(mesh 'box') crosses the periodic axis x"));
}
