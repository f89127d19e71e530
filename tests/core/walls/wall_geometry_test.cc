// Closest points on wall primitives against brute-force oracles: for triangles, an independent
// "project, else nearest of the three segments" construction; for cylinders and cones, dense
// sampling of the surface (no sample may be closer than the answer, and the answer must be within
// the sampling resolution of the best sample), plus analytic cases.
#include "core/walls/wall_geometry.h"

#include <algorithm>
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <random>

using namespace demcal::core;

namespace {

constexpr double kPi = std::numbers::pi;

Vec3 Unit(const Vec3& v) { return v / Norm(v); }

// Independent oracle: the projection if it falls inside, else the best of the three edges.
TriangleClosestPoint BruteClosest(const Vec3& p, const std::array<Vec3, 3>& v) {
  const Vec3 n = Unit(Cross(v[1] - v[0], v[2] - v[0]));
  const Vec3 q = p - Dot(p - v[0], n) * n;
  bool inside = true;
  for (int k = 0; k < 3; ++k) {
    inside = inside && Dot(Cross(v[(k + 1) % 3] - v[k], q - v[k]), n) > 0;
  }
  if (inside) return {q, TriangleRegion::kFace};
  TriangleClosestPoint best{{}, TriangleRegion::kFace};
  double best_d2 = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 3; ++k) {
    const Vec3 a = v[k], b = v[(k + 1) % 3];
    const double t = std::clamp(Dot(p - a, b - a) / Norm2(b - a), 0.0, 1.0);
    const Vec3 x = a + t * (b - a);
    const TriangleRegion region = t == 0 ? static_cast<TriangleRegion>(4 + k)
                                         : (t == 1 ? static_cast<TriangleRegion>(4 + (k + 1) % 3)
                                                   : static_cast<TriangleRegion>(1 + k));
    if (Norm2(p - x) < best_d2) best = {x, region}, best_d2 = Norm2(p - x);
  }
  return best;
}

// Samples a surface of revolution given by its meridian s ∈ [0, 1] → (radius, height) and
// returns the smallest distance from p to any sample.
double SampledDistance(const Vec3& p, const Vec3& axis_point, const Vec3& axis,
                       const std::function<std::array<double, 2>(double)>& meridian, int n_phi,
                       int n_s) {
  const Vec3 e1 = AnyPerpendicular(axis), e2 = Cross(axis, e1);
  double best = std::numeric_limits<double>::infinity();
  for (int j = 0; j <= n_s; ++j) {
    const auto [rho, h] = meridian(static_cast<double>(j) / n_s);
    for (int i = 0; i < n_phi; ++i) {
      const double phi = 2 * kPi * i / n_phi;
      const Vec3 x = axis_point + h * axis + rho * (std::cos(phi) * e1 + std::sin(phi) * e2);
      best = std::min(best, Norm2(p - x));
    }
  }
  return std::sqrt(best);
}

// Checks shared by every primitive: the point is at |distance| from p, the normal is unit and
// points from the surface to p (with the sign of distance on the open surface).
void CheckConsistent(const WallProximity& w, const Vec3& p) {
  CHECK(std::abs(Norm(w.normal) - 1) < 1e-12);
  CHECK(std::abs(Norm(p - w.point_m) - std::abs(w.distance_m)) < 1e-12);
  CHECK(Norm(p - w.point_m - w.distance_m * w.normal) < 1e-12);
  if (w.on_edge) CHECK(w.distance_m >= 0);
}

Vec3 RandomUnit(std::mt19937_64& rng) {
  std::normal_distribution<double> g;
  return Unit(Vec3{g(rng), g(rng), g(rng)});
}

}  // namespace

TEST_CASE("triangle closest point matches the brute-force oracle in every region",
          "[unit][geometry]") {
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> u(-1, 1);
  std::array<int, 7> seen{};
  for (int trial = 0; trial < 20000; ++trial) {
    const std::array<Vec3, 3> v = {Vec3{u(rng), u(rng), u(rng)}, Vec3{u(rng), u(rng), u(rng)},
                                   Vec3{u(rng), u(rng), u(rng)}};
    if (Norm(Cross(v[1] - v[0], v[2] - v[0])) < 1e-3) continue;
    const Vec3 p{2 * u(rng), 2 * u(rng), 2 * u(rng)};
    const TriangleClosestPoint got = ClosestPointOnTriangle(p, v[0], v[1], v[2]);
    const TriangleClosestPoint want = BruteClosest(p, v);
    INFO("trial " << trial);
    REQUIRE(Norm(got.point_m - want.point_m) < 1e-12);
    CHECK(got.region == want.region);
    ++seen[static_cast<int>(got.region)];
  }
  for (int r = 0; r < 7; ++r) {
    INFO("region " << r);
    CHECK(seen[r] > 100);
  }
}

TEST_CASE("plane closest point is the orthogonal projection", "[unit][geometry]") {
  const PlaneSurface plane{{1, 2, 3}, Unit(Vec3{1, -1, 2})};
  REQUIRE(plane.IsValid(nullptr));
  const Vec3 p{0.3, 4, -2};
  const WallProximity w = ClosestOnPlane(plane, p);
  CheckConsistent(w, p);
  CHECK(w.distance_m == Approx(Dot(p - plane.point_m, plane.normal)).epsilon(1e-14));
  CHECK(std::abs(Dot(w.point_m - plane.point_m, plane.normal)) < 1e-12);
  CHECK(w.distance_m < 0);  // p is behind the plane
}

TEST_CASE("cylinder closest point matches dense sampling, inside and outside, finite and not",
          "[unit][geometry]") {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-1, 1);
  for (const bool inside : {true, false}) {
    for (const bool finite : {true, false}) {
      CylinderSurface cyl;
      cyl.axis_point_m = {0.1, -0.2, 0.3};
      cyl.axis = Unit(Vec3{0.2, 0.3, 1});
      cyl.radius_m = 0.5;
      cyl.inside = inside;
      if (finite) cyl.axial_min_m = -0.4, cyl.axial_max_m = 0.6;
      REQUIRE(cyl.IsValid(nullptr));
      int rims = 0;
      for (int trial = 0; trial < 40; ++trial) {
        const Vec3 p = cyl.axis_point_m + Vec3{1.2 * u(rng), 1.2 * u(rng), 1.2 * u(rng)};
        const WallProximity w = ClosestOnCylinder(cyl, p);
        INFO("inside " << inside << " finite " << finite << " trial " << trial);
        CheckConsistent(w, p);
        const double h = Dot(p - cyl.axis_point_m, cyl.axis);
        const double r = Norm(p - cyl.axis_point_m - h * cyl.axis);
        const double hp = Dot(w.point_m - cyl.axis_point_m, cyl.axis);
        CHECK(std::abs(Norm(w.point_m - cyl.axis_point_m - hp * cyl.axis) - 0.5) < 1e-12);
        CHECK(hp >= cyl.axial_min_m - 1e-12);
        CHECK(hp <= cyl.axial_max_m + 1e-12);
        if (!w.on_edge) {
          CHECK(w.distance_m == Approx(inside ? 0.5 - r : r - 0.5).margin(1e-12));
        }
        rims += w.on_edge;
        // Infinite: sample a window around the centre's height (the nearest point is level).
        const double lo = finite ? cyl.axial_min_m : h - 1, hi = finite ? cyl.axial_max_m : h + 1;
        const double sampled = SampledDistance(
            p, cyl.axis_point_m, cyl.axis,
            [&](double s) {
              return std::array<double, 2>{0.5, lo + s * (hi - lo)};
            },
            1024, 512);
        CHECK(sampled >= std::abs(w.distance_m) - 1e-12);
        CHECK(sampled <= std::abs(w.distance_m) + 2 * kPi * 0.5 / 1024 + (hi - lo) / 512);
      }
      if (finite) CHECK(rims > 0);
      if (!finite) CHECK(rims == 0);
    }
  }
}

TEST_CASE("cylinder rim: beyond a finite end the nearest point is on the rim circle",
          "[unit][geometry]") {
  CylinderSurface cyl{.axis_point_m = {0, 0, 0},
                      .axis = {0, 0, 1},
                      .radius_m = 1,
                      .axial_min_m = 0,
                      .axial_max_m = 2,
                      .inside = true};
  const Vec3 p{0.25, 0, 3};
  const WallProximity w = ClosestOnCylinder(cyl, p);
  CHECK(w.on_edge);
  CHECK(w.point_m.x == Approx(1));
  CHECK(w.point_m.z == Approx(2));
  CHECK(w.distance_m == Approx(std::hypot(0.75, 1.0)));
  // Inside the tube the distance is signed: negative once the centre is outside the wall.
  CHECK(ClosestOnCylinder(cyl, {1.1, 0, 1}).distance_m == Approx(-0.1));
  CHECK(ClosestOnCylinder(cyl, {0.9, 0, 1}).normal.x == Approx(-1));
}

TEST_CASE("cylinder side distance is exactly ClosestOnCylinder's on the open surface",
          "[unit][geometry]") {
  // The contact sweep and the wall rebuild decide "not touching" from CylinderSideDistance and
  // only then ask ClosestOnCylinder: the two must agree to the last bit, or results would depend
  // on which path a candidate took.
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-1, 1);
  int level = 0, beyond = 0;
  for (const bool inside : {true, false}) {
    for (const bool shell : {true, false}) {
      CylinderSurface cyl{.axis_point_m = {0.1, -0.2, 0.3}, .axis = Unit(Vec3{0.2, 0.3, 1}),
                          .radius_m = 0.5, .axial_min_m = -0.4, .axial_max_m = 0.6,
                          .inside = inside};
      for (int trial = 0; trial < 200; ++trial) {
        const Vec3 p = cyl.axis_point_m + Vec3{1.2 * u(rng), 1.2 * u(rng), 1.2 * u(rng)};
        WallProximity w = ClosestOnCylinder(cyl, p);
        if (shell && w.distance_m < 0) w.distance_m = -w.distance_m;  // ShellSide
        double d = -1;
        const bool level_with_side = CylinderSideDistance(cyl, shell, p, d);
        INFO("inside " << inside << " shell " << shell << " trial " << trial);
        CHECK(level_with_side == !w.on_edge);
        if (level_with_side) CHECK(d == w.distance_m);  // bit for bit, not approximately
        level += level_with_side, beyond += !level_with_side;
      }
    }
  }
  CHECK(level > 100);
  CHECK(beyond > 100);
}

TEST_CASE("cone frustum closest point matches dense sampling", "[unit][geometry]") {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-1, 1);
  for (const bool inside : {true, false}) {
    for (const bool swapped : {false, true}) {
      ConeFrustumSurface cone;
      cone.axis_point_m = {0.3, 0.1, -0.2};
      cone.axis = RandomUnit(rng);
      cone.height0_m = 0.1, cone.radius0_m = 0.05;  // orifice
      cone.height1_m = 0.8, cone.radius1_m = 0.6;   // top
      if (swapped) {
        std::swap(cone.height0_m, cone.height1_m);
        std::swap(cone.radius0_m, cone.radius1_m);
      }
      cone.inside = inside;
      REQUIRE(cone.IsValid(nullptr));
      const double h_lo = 0.1, h_hi = 0.8;
      auto rho = [](double h) { return 0.05 + (h - 0.1) * (0.55 / 0.7); };
      int rims = 0, interior = 0;
      for (int trial = 0; trial < 60; ++trial) {
        const Vec3 p =
            cone.axis_point_m + 0.45 * (1 + u(rng)) * cone.axis + 0.8 * u(rng) * RandomUnit(rng);
        const WallProximity w = ClosestOnConeFrustum(cone, p);
        INFO("inside " << inside << " swapped " << swapped << " trial " << trial);
        CheckConsistent(w, p);
        const double hp = Dot(w.point_m - cone.axis_point_m, cone.axis);
        const double rp = Norm(w.point_m - cone.axis_point_m - hp * cone.axis);
        CHECK(hp >= h_lo - 1e-12);
        CHECK(hp <= h_hi + 1e-12);
        CHECK(std::abs(rp - rho(hp)) < 1e-12);
        rims += w.on_edge;
        const double h = Dot(p - cone.axis_point_m, cone.axis);
        const double r = Norm(p - cone.axis_point_m - h * cone.axis);
        if (!w.on_edge) {
          ++interior;
          // On the open surface the sign says which side of the (extended) wall line, in the
          // meridian plane, the centre is on.
          const bool centre_inside = r < rho(h);
          if (std::abs(w.distance_m) > 1e-9) CHECK((w.distance_m > 0) == (centre_inside == inside));
        }
        const double sampled = SampledDistance(
            p, cone.axis_point_m, cone.axis,
            [&](double s) {
              const double hs = h_lo + s * (h_hi - h_lo);
              return std::array<double, 2>{rho(hs), hs};
            },
            1024, 512);
        CHECK(sampled >= std::abs(w.distance_m) - 1e-12);
        CHECK(sampled <= std::abs(w.distance_m) + 2 * kPi * 0.6 / 1024 + 1.0 / 512);
      }
      CHECK(rims > 0);
      CHECK(interior > 0);
    }
  }
}

TEST_CASE("funnel: a centre on the axis is rho(h) cos(alpha) from the wall", "[unit][geometry]") {
  // 2D: the distance from (0, h) to the wall line r = r0 + (h - h0) tan(alpha) is rho(h)
  // cos(alpha).
  const ConeFrustumSurface funnel{.axis_point_m = {0, 0, 0},
                                  .axis = {0, 0, 1},
                                  .height0_m = 0,
                                  .radius0_m = 0.01,
                                  .height1_m = 0.1,
                                  .radius1_m = 0.05};
  const double alpha = std::atan((0.05 - 0.01) / 0.1);
  const double h = 0.06, rho = 0.01 + h * std::tan(alpha);
  const WallProximity w = ClosestOnConeFrustum(funnel, {0, 0, h});
  CHECK_FALSE(w.on_edge);
  CHECK(w.distance_m == Approx(rho * std::cos(alpha)).epsilon(1e-12));
  CHECK(w.normal.z == Approx(std::sin(alpha)).epsilon(1e-12));  // up and in, towards the centre
  // Below the orifice the nearest point is on the orifice rim.
  const WallProximity below = ClosestOnConeFrustum(funnel, {0.002, 0, -0.01});
  CHECK(below.on_edge);
  CHECK(below.distance_m == Approx(std::hypot(0.008, 0.01)).epsilon(1e-12));
}

TEST_CASE("a cone frustum with equal radii is a finite cylinder", "[unit][geometry]") {
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> u(-1, 1);
  const Vec3 axis = Unit(Vec3{1, 2, 3});
  const ConeFrustumSurface cone{.axis_point_m = {0, 1, 0},
                                .axis = axis,
                                .height0_m = -0.5,
                                .radius0_m = 0.4,
                                .height1_m = 0.7,
                                .radius1_m = 0.4};
  const CylinderSurface cyl{.axis_point_m = {0, 1, 0},
                            .axis = axis,
                            .radius_m = 0.4,
                            .axial_min_m = -0.5,
                            .axial_max_m = 0.7,
                            .inside = true};
  for (int trial = 0; trial < 1000; ++trial) {
    const Vec3 p{u(rng), 1 + u(rng), u(rng)};
    const WallProximity a = ClosestOnConeFrustum(cone, p), b = ClosestOnCylinder(cyl, p);
    CHECK(a.on_edge == b.on_edge);
    CHECK(a.distance_m == Approx(b.distance_m).margin(1e-12));
    CHECK(Norm(a.point_m - b.point_m) < 1e-12);
    CHECK(Norm(a.normal - b.normal) < 1e-12);
  }
}

TEST_CASE("primitive validation names the bad field", "[unit][geometry]") {
  std::string error;
  CHECK_FALSE(PlaneSurface{{0, 0, 0}, {0, 0, 2}}.IsValid(&error));
  CHECK_THAT(error, Catch::Contains("normal"));
  CylinderSurface cyl;
  CHECK_FALSE(cyl.IsValid(&error));
  CHECK_THAT(error, Catch::Contains("radius_m"));
  cyl.radius_m = 1;
  cyl.axial_min_m = 2, cyl.axial_max_m = 1;
  CHECK_FALSE(cyl.IsValid(&error));
  CHECK_THAT(error, Catch::Contains("axial_min_m"));
  ConeFrustumSurface cone{.axis_point_m = {},
                          .axis = {0, 0, 1},
                          .height0_m = 1,
                          .radius0_m = 0,
                          .height1_m = 1,
                          .radius1_m = 1};
  CHECK_FALSE(cone.IsValid(&error));
  CHECK_THAT(error, Catch::Contains("height"));
  cone.height1_m = 2;
  CHECK(cone.IsValid(&error));  // a full cone with its apex at height 1
  cone.radius1_m = 0;
  CHECK_FALSE(cone.IsValid(&error));
}
