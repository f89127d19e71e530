// Scene::IsValid against the physical limits (core/limits/physical_limits.h): magnitudes that are
// finite but absurd are refused naming the field and the range, and the derived motion checks
// refuse a speed that carries a body further than the smallest radius in one time step, with
// the boundary computed from the Rayleigh time step, not assumed.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "core/bodies/clump_shapes.h"
#include "core/limits/physical_limits.h"
#include "core/scene/scene.h"

using namespace demcal::core;

namespace {

// 50 glass beads (d = 2 mm, E = 5 MPa) in a 20 × 20 × 40 mm box with a floor.
Scene Beads() {
  Scene s;
  s.materials = {{"glass", 5e6, 0.25, 2500}};
  s.species = {{"beads", 0, {}, {}}};
  s.species[0].size.diameter_m = 0.002;
  s.pair_parameters = {PairParameters{}};
  s.domain_min_m = {0, 0, 0};
  s.domain_max_m = {0.02, 0.02, 0.04};
  s.walls = {Wall("floor", 0, PlaneSurface{{0, 0, 0}, {0, 0, 1}})};
  s.fills = {{0, {0.001, 0.001, 0.001}, {0.019, 0.019, 0.03}, 50}};
  s.time.duration_s = 0.01;
  return s;
}

std::string ErrorOf(const Scene& s) {
  std::string error;
  return s.IsValid(&error) ? "" : error;
}

// The time step the scene runs with (its Rayleigh fraction of the Rayleigh time).
double Step(const Scene& s) { return s.time.rayleigh_fraction * RayleighTime(s); }

}  // namespace

TEST_CASE("the base scene of the limit tests is valid", "[unit]") {
  CHECK(ErrorOf(Beads()).empty());
}

TEST_CASE("finite but absurd magnitudes are refused with the field and the range", "[unit]") {
  Scene s = Beads();
  s.gravity_m_s2 = {0, 0, -1e308};
  CHECK_THAT(ErrorOf(s), Catch::Contains("'gravity_m_s2' has magnitude 1e+308 m/s2, outside the "
                                         "allowed range [0, 10000] m/s2"));
  s = Beads();
  s.fills[0].velocity_m_s = {1e308, 0, 0};
  CHECK_THAT(ErrorOf(s), Catch::Contains("'fills[0].velocity_m_s' has magnitude 1e+308 m/s"));
  s = Beads();
  s.materials[0].youngs_modulus_Pa = 1e300;
  CHECK_THAT(ErrorOf(s), Catch::Contains("materials[0].youngs_modulus_Pa"));
  s = Beads();
  s.walls[0].velocity_m_s = {0, 0, 1e5};
  CHECK_THAT(ErrorOf(s), Catch::Contains("'walls[0].velocity_m_s' has magnitude 100000 m/s"));
  s = Beads();
  s.particles = {{0, {0.01, 0.01, 0.035}}};
  s.particles[0].angular_velocity_rad_s = {0, 1e300, 0};
  CHECK_THAT(ErrorOf(s), Catch::Contains("particles[0].angular_velocity_rad_s"));
  s = Beads();
  s.domain_max_m.z = 1e300;
  CHECK_THAT(ErrorOf(s), Catch::Contains("'domain.max_m[2]' = 1e+300 m is outside the allowed "
                                         "range [-1e+06, 1e+06] m"));
}

TEST_CASE("a factory region velocity must be a speed and keep the region in the domain",
          "[unit]") {
  Scene s = Beads();
  s.fills.clear();
  FactorySpec f;
  f.species = {0};
  f.mass_fractions = {1};
  f.mass_rate_kg_s = 1e-3;
  f.region = InsertionRegion::Box({0.001, 0.001, 0.03}, {0.019, 0.019, 0.039});
  s.factories = {f};
  REQUIRE(ErrorOf(s).empty());
  s.factories[0].region_velocity_m_s = {1e308, 0, 0};
  CHECK_THAT(ErrorOf(s), Catch::Contains("'factories[0].region_velocity_m_s' has magnitude"));
  // 0.1 m/s for the 0.01 s of the run moves the region 1 mm: it stays in the domain.
  s.factories[0].region_velocity_m_s = {0, 0, -0.1};
  CHECK(ErrorOf(s).empty());
  // 1 m/s moves it 10 mm sideways, 9 mm past the domain's side at x = 20 mm.
  s.factories[0].region_velocity_m_s = {1, 0, 0};
  CHECK_THAT(ErrorOf(s), Catch::Contains("moves the region by 0.01 m over its 0.01 s of "
                                         "insertion, to [0.011, 0.029] m along x"));
}

TEST_CASE("a speed that crosses more than a radius in one time step is refused", "[unit]") {
  Scene s = Beads();
  s.gravity_m_s2 = {0, 0, 0};
  s.particles = {{0, {0.01, 0.01, 0.035}}};
  const double radius = 0.001, dt = Step(s);
  // kMaxStepTravelRadii = 1: the boundary speed is one radius per step.
  s.particles[0].velocity_m_s = {0, 0, -0.99 * radius / dt};
  CHECK(ErrorOf(s).empty());
  s.particles[0].velocity_m_s = {0, 0, -1.01 * radius / dt};
  CHECK_THAT(ErrorOf(s), Catch::Contains("field 'particles[0].velocity_m_s': a speed of"));
  CHECK_THAT(ErrorOf(s), Catch::Contains("more than 1 × the smallest particle radius 0.001 m"));
  // A fall through the domain adds sqrt(2 g H) to the speed: gravity alone can cross a radius
  // in one step. With a 1 m tall domain the boundary gravity is inside kGravity.
  s = Beads();
  s.domain_max_m.z = 1.0;
  const double g = 0.5 * std::pow(radius / Step(s), 2) / 1.0;  // v_fall = r / dt
  REQUIRE(limits::kGravity.Contains(1.01 * g));
  s.gravity_m_s2 = {0, 0, -1.01 * g};
  CHECK_THAT(ErrorOf(s), Catch::Contains("field 'gravity_m_s2': a speed of 0 m/s ("));
  CHECK_THAT(ErrorOf(s), Catch::Contains("after a free fall of 1 m through the domain"));
  s.gravity_m_s2 = {0, 0, -0.98 * g};
  CHECK(ErrorOf(s).empty());
  // Earth gravity and a centrifuge-scale 1000 g pass in the 40 mm box.
  s = Beads();
  s.gravity_m_s2 = {0, 0, -9.81e3};
  CHECK(ErrorOf(s).empty());
}

TEST_CASE("clump semi-axes are refused outside the range the builder is meaningful for",
          "[unit]") {
  std::string why;
  CHECK(CheckEllipsoidSemiAxes({2, 1.5, 1}, &why));
  CHECK(CheckEllipsoidSemiAxes({10, 1, 1}, &why));  // the aspect-ratio bound itself
  CHECK(CheckEllipsoidSemiAxes({2e-3, 1e-3, 1e-3}, &why));
  CHECK_FALSE(CheckEllipsoidSemiAxes({1e300, 1, 1e-300}, &why));
  CHECK_THAT(why, Catch::Contains("outside the allowed range [1e-09, 1e+09]"));
  CHECK_FALSE(CheckEllipsoidSemiAxes({10.5, 1, 1}, &why));
  CHECK_THAT(why, Catch::Contains("aspect ratio a/c = 10.5, outside the allowed range [1, 10]"));
  CHECK_FALSE(CheckEllipsoidSemiAxes({1, 2, 1}, &why));
  CHECK_THAT(why, Catch::Contains("a >= b >= c > 0"));
  CHECK_FALSE(CheckEllipsoidSemiAxes({2, 1, std::nan("")}, &why));
  ShapeApproximation shape;
  CHECK_FALSE(ApproximateEllipsoid({1e300, 1, 1e-300}, 3, &shape, &why));
}

TEST_CASE("round walls: radii, heights and finite axial ends within the table's limits",
          "[unit]") {
  Scene s = Beads();
  CylinderSurface silo{{0.01, 0.01, 0}, {0, 0, 1}, 0.009};  // unbounded along its axis
  s.walls.push_back(Wall("silo", 0, silo));
  CHECK(ErrorOf(s).empty());
  s.walls[1] = Wall("silo", 0, CylinderSurface{{0.01, 0.01, 0}, {0, 0, 1}, 1e300});
  CHECK_THAT(ErrorOf(s), Catch::Contains("walls[1].radius_m"));
  silo.axial_max_m = 1e300;
  s.walls[1] = Wall("silo", 0, silo);
  CHECK_THAT(ErrorOf(s), Catch::Contains("walls[1].axial_max_m"));
  const ConeFrustumSurface funnel{{0.01, 0.01, 0.02}, {0, 0, 1}, 0, 0.003, 0.01, 0.009};
  s.walls[1] = Wall("funnel", 0, funnel);
  CHECK(ErrorOf(s).empty());
  ConeFrustumSurface tall = funnel;
  tall.height1_m = 1e300;
  s.walls[1] = Wall("funnel", 0, tall);
  CHECK_THAT(ErrorOf(s), Catch::Contains("walls[1].height1_m"));
  ConeFrustumSurface wide = funnel;
  wide.radius1_m = 1e300;
  s.walls[1] = Wall("funnel", 0, wide);
  CHECK_THAT(ErrorOf(s), Catch::Contains("walls[1].radius1_m"));
}
