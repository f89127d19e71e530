// Sphere–wall contacts on every wall shape against the same case on plane walls (DEM core II,
// geometry): a sphere resting on a horizontal cylinder's inside, a tilted cone's inside (its
// lowest generatrix horizontal) or a mesh box has the Hertz rest overlap of a sphere on a flat,
// δ = (m g / ((4/3) E* sqrt(R)))^{2/3} (Johnson, Contact Mechanics, 1985, §4.2), and the walls
// carry exactly its weight (static equilibrium). The wall contact treats the surface as locally
// flat (R* = R), so the rest heights agree with the plane case to rounding.
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "core/walls/wall_test_support.h"

using namespace demcal::core;
using namespace demcal::core::wall_test;

namespace {

constexpr double kRadius = 0.005;
constexpr double kG = 9.81;

struct Rest {
  Vec3 position;
  Vec3 force_on_walls;
  Vec3 torque_on_walls;  // about the origin
  size_t contacts = 0;
};

// One sphere released at `start` under gravity g among `walls`; state after 0.02 s.
Rest RestAmong(const std::vector<Wall>& walls, const Vec3& start, const Vec3& gravity) {
  Scene s = OneMaterialScene(2 * kRadius);
  s.walls = walls;
  s.gravity_m_s2 = gravity;
  s.particles = {{0, start, {}, {}, 2 * kRadius, {}}};
  s.domain_min_m = {-0.2, -0.2, -0.2};
  s.domain_max_m = {0.2, 0.2, 0.2};
  Simulation sim(s, {.threads = 1});
  InitializeOrFail(sim);
  REQUIRE(sim.Run(0.02).ok());
  Rest r{sim.particles().position_m[0], {}, {}, sim.ActiveContacts()};
  for (const WallLoad& load : sim.WallLoads()) {
    CHECK(load.point_m == Vec3{});
    r.force_on_walls += load.force_N;
    r.torque_on_walls += load.torque_N_m;
  }
  return r;
}

}  // namespace

TEST_CASE("a sphere resting on a cylinder, cone or mesh box matches the plane case",
          "[physics]") {
  const Scene s = OneMaterialScene(2 * kRadius);
  const double weight = SphereMass(s, kRadius) * kG;
  const double delta = HertzRestOverlap(s, kRadius, weight);
  const Vec3 start{0.02, 0, kRadius - delta};  // off the origin: the torque is x × F
  const Vec3 down{0, 0, -kG};

  const Rest plane = RestAmong({PlaneWall{"floor", {}, {0, 0, 1}, 0, {}}}, start, down);
  CHECK(plane.position.z == Approx(kRadius - delta).margin(1e-3 * delta));
  CHECK(plane.force_on_walls.z == Approx(-weight).epsilon(1e-6));
  CHECK(plane.torque_on_walls.y == Approx(0.02 * weight).epsilon(1e-6));
  CHECK(plane.contacts == 1);

  std::vector<Wall> walls;
  SECTION("inside of a horizontal cylinder") {
    walls.push_back(Wall("pipe", 0,
                         CylinderSurface{.axis_point_m = {0, 0, 0.05}, .axis = {1, 0, 0},
                                         .radius_m = 0.05, .axial_min_m = -0.1,
                                         .axial_max_m = 0.1}));
  }
  SECTION("inside of a cone whose lowest generatrix is horizontal") {
    // Half-angle α with tan α = (r1 − r0)/(h1 − h0); the axis tilted up by α puts the lowest
    // generatrix at z = p.z − r0 cos α, which is 0 here.
    const double alpha = std::atan(0.2);
    walls.push_back(Wall("cone", 0,
                         ConeFrustumSurface{.axis_point_m = {-0.1, 0, 0.02 * std::cos(alpha)},
                                            .axis = {std::cos(alpha), 0, std::sin(alpha)},
                                            .height0_m = 0, .radius0_m = 0.02,
                                            .height1_m = 0.2, .radius1_m = 0.06}));
  }
  SECTION("floor of a mesh box, on the diagonal the two floor triangles share") {
    walls.push_back(MeshBox("box", {-0.05, -0.05, 0}, {0.05, 0.05, 0.1}, /*open_top=*/true));
    const Rest on_edge = RestAmong(walls, {0, 0, kRadius - delta}, down);
    CHECK(on_edge.position.z == Approx(kRadius - delta).margin(1e-3 * delta));
    CHECK(on_edge.contacts == 1);
  }
  const Rest r = RestAmong(walls, start, down);
  CHECK(std::abs(r.position.z - plane.position.z) < 1e-12);
  CHECK(std::abs(r.position.x - plane.position.x) < 1e-12);
  CHECK(std::abs(r.position.y) < 1e-12);
  CHECK(r.force_on_walls.z == Approx(-weight).epsilon(1e-6));
  CHECK(std::abs(r.force_on_walls.x) < 1e-9 * weight);
  CHECK(r.torque_on_walls.y == Approx(0.02 * weight).epsilon(1e-6));
  CHECK(r.contacts == 1);
}

TEST_CASE("a sphere pressed into a mesh box corner rests like in a plane box", "[physics]") {
  // Gravity towards the corner (hi.x, hi.y, lo.z): three face contacts at once, each with its
  // own history; the three walls carry the weight.
  const Scene s = OneMaterialScene(2 * kRadius);
  const Vec3 g = Vec3{1, 1, -1} * (kG / std::sqrt(3.0));
  const Vec3 lo{-0.05, -0.05, 0}, hi{0.05, 0.05, 0.1};
  const Vec3 start{hi.x - kRadius, hi.y - kRadius, kRadius};
  const Rest planes = RestAmong(BoxInnerFaces("box", lo, hi, 0, true), start, g);
  const Rest mesh = RestAmong({MeshBox("box", lo, hi, true)}, start, g);
  CHECK(planes.contacts == 3);
  CHECK(mesh.contacts == 3);
  CHECK(Norm(mesh.position - planes.position) < 1e-12);
  const Vec3 weight = g * SphereMass(s, kRadius);
  CHECK(Norm(mesh.force_on_walls - weight) < 1e-6 * Norm(weight));
  CHECK(Norm(planes.force_on_walls - weight) < 1e-6 * Norm(weight));
}

TEST_CASE("a sphere rolling across the shared edge of two coplanar mesh triangles feels a plane",
          "[physics]") {
  // Pure rolling (ω = v/R) without rolling resistance keeps a constant speed (no slip, no
  // friction work); crossing the diagonal of a two-triangle plate must not bump the sphere or
  // double its support.
  const Scene base = OneMaterialScene(2 * kRadius);
  const double delta = HertzRestOverlap(base, kRadius, SphereMass(base, kRadius) * kG);
  const double v = 0.5;
  struct Sample {
    double z, vx;
    size_t contacts;
  };
  auto roll = [&](const Wall& floor) {
    Scene s = base;
    s.walls = {floor};
    s.particles = {{0, {-0.03, 0.001, kRadius - delta}, {v, 0, 0}, {0, v / kRadius, 0},
                    2 * kRadius, {}}};
    s.domain_min_m = {-0.1, -0.1, -0.1};
    s.domain_max_m = {0.1, 0.1, 0.1};
    Simulation sim(s, {.threads = 1});
    InitializeOrFail(sim);
    std::vector<Sample> samples;
    Simulation::Observer every_step{1, [&](const Simulation& sm) {
                                      samples.push_back({sm.particles().position_m[0].z,
                                                         sm.particles().velocity_m_s[0].x,
                                                         sm.ActiveContacts()});
                                      return true;
                                    }};
    REQUIRE(sim.Run(0.12, every_step).ok());
    CHECK(sim.particles().position_m[0].x > 0.02);  // it crossed the diagonal near x = 0
    return samples;
  };
  const std::vector<Sample> plane = roll(PlaneWall{"floor", {}, {0, 0, 1}, 0, {}});
  const std::vector<Sample> mesh = roll(MeshPlate("plate", 0.05, 0));
  REQUIRE(plane.size() == mesh.size());
  double dz = 0, dv = 0, z_spread = 0, v_spread = 0;
  bool one_contact = true;
  for (size_t k = 0; k < mesh.size(); ++k) {
    dz = std::max(dz, std::abs(mesh[k].z - plane[k].z));
    dv = std::max(dv, std::abs(mesh[k].vx - plane[k].vx));
    z_spread = std::max(z_spread, std::abs(mesh[k].z - mesh[0].z));
    v_spread = std::max(v_spread, std::abs(mesh[k].vx - v));
    one_contact = one_contact && mesh[k].contacts == 1;
  }
  INFO("max |z_mesh - z_plane| = " << dz << " m, max |v_mesh - v_plane| = " << dv
       << " m/s, height spread " << z_spread << " m, speed spread " << v_spread << " m/s");
  CHECK(one_contact);
  CHECK(dz < 1e-12);
  CHECK(dv < 1e-12);
  CHECK(z_spread < 1e-3 * delta);
  CHECK(v_spread < 1e-6 * v);
}
