#include "core/bodies/clump_shapes.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <map>
#include <numbers>
#include <vector>

using namespace demcal::core;

namespace {

constexpr double kPi = std::numbers::pi;

// Closed box [lo, hi] as 12 outward (counter-clockwise from outside) triangles.
std::vector<Triangle> Box(const Vec3& lo, const Vec3& hi) {
  auto p = [&](int i, int j, int k) {
    return Vec3{i ? hi.x : lo.x, j ? hi.y : lo.y, k ? hi.z : lo.z};
  };
  auto quad = [&](std::vector<Triangle>& t, Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
    t.push_back({a, b, c});
    t.push_back({a, c, d});
  };
  std::vector<Triangle> t;
  quad(t, p(0, 0, 0), p(0, 1, 0), p(1, 1, 0), p(1, 0, 0));  // z = lo, normal −z
  quad(t, p(0, 0, 1), p(1, 0, 1), p(1, 1, 1), p(0, 1, 1));  // z = hi, normal +z
  quad(t, p(0, 0, 0), p(1, 0, 0), p(1, 0, 1), p(0, 0, 1));  // y = lo, normal −y
  quad(t, p(0, 1, 0), p(0, 1, 1), p(1, 1, 1), p(1, 1, 0));  // y = hi, normal +y
  quad(t, p(0, 0, 0), p(0, 0, 1), p(0, 1, 1), p(0, 1, 0));  // x = lo, normal −x
  quad(t, p(1, 0, 0), p(1, 1, 0), p(1, 1, 1), p(1, 0, 1));  // x = hi, normal +x
  return t;
}

std::vector<Triangle> Transformed(const std::vector<Triangle>& mesh, const Quaternion& q,
                                  const Vec3& shift) {
  std::vector<Triangle> out = mesh;
  for (auto& tri : out) {
    for (auto& v : tri) v = shift + Rotate(q, v);
  }
  return out;
}

// Icosphere of radius r centred at c: icosahedron subdivided `levels` times, vertices on the
// sphere, faces oriented outward.
std::vector<Triangle> Icosphere(double r, const Vec3& c, int levels) {
  const double g = (1 + std::sqrt(5.0)) / 2;
  std::vector<Vec3> v = {{-1, g, 0},  {1, g, 0},  {-1, -g, 0}, {1, -g, 0}, {0, -1, g},  {0, 1, g},
                         {0, -1, -g}, {0, 1, -g}, {g, 0, -1},  {g, 0, 1},  {-g, 0, -1}, {-g, 0, 1}};
  std::vector<std::array<int, 3>> f = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                       {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                       {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                       {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  for (auto& p : v) p = p / Norm(p);
  for (int l = 0; l < levels; ++l) {
    std::map<std::pair<int, int>, int> mid;
    auto midpoint = [&](int a, int b) {
      const auto key = std::minmax(a, b);
      auto it = mid.find(key);
      if (it != mid.end()) return it->second;
      const Vec3 m = v[a] + v[b];
      v.push_back(m / Norm(m));
      return mid[key] = static_cast<int>(v.size()) - 1;
    };
    std::vector<std::array<int, 3>> next;
    for (const auto& t : f) {
      const int ab = midpoint(t[0], t[1]), bc = midpoint(t[1], t[2]), ca = midpoint(t[2], t[0]);
      next.push_back({t[0], ab, ca});
      next.push_back({t[1], bc, ab});
      next.push_back({t[2], ca, bc});
      next.push_back({ab, bc, ca});
    }
    f = next;
  }
  std::vector<Triangle> out;
  for (const auto& t : f) {
    Triangle tri = {c + r * v[t[0]], c + r * v[t[1]], c + r * v[t[2]]};
    const Vec3 n = Cross(tri[1] - tri[0], tri[2] - tri[0]);
    if (Dot(n, tri[0] - c) < 0) std::swap(tri[1], tri[2]);
    out.push_back(tri);
  }
  return out;
}

// Smallest distance from the centre to a face plane (radius of the inscribed ball).
double InscribedRadius(const std::vector<Triangle>& mesh, const Vec3& c) {
  double r = INFINITY;
  for (const auto& t : mesh) {
    const Vec3 n = Cross(t[1] - t[0], t[2] - t[0]);
    r = std::min(r, std::abs(Dot(t[0] - c, n)) / Norm(n));
  }
  return r;
}

}  // namespace

TEST_CASE("clump shapes: ellipsoid chains have the ellipsoid's volume for n = 1..5",
          "[clump][unit]") {
  for (const Vec3 axes : {Vec3{1.2, 1, 1}, Vec3{1.5, 1, 1}, Vec3{2, 1, 1}, Vec3{3, 1, 1},
                          Vec3{4, 1, 1}, Vec3{3, 2, 1}, Vec3{2e-3, 1.5e-3, 1e-3}}) {
    for (int n = 1; n <= 5; ++n) {
      ShapeApproximation s;
      std::string err;
      REQUIRE(ApproximateEllipsoid(axes, n, &s, &err));
      INFO("semi-axes (" << axes.x << ", " << axes.y << ", " << axes.z << "), n = " << n << ", "
                         << s.construction);
      REQUIRE(s.spheres.size() == static_cast<size_t>(n));
      CHECK(s.target_volume_m3 == Approx(4.0 / 3.0 * kPi * axes.x * axes.y * axes.z));
      CHECK(std::abs(s.volume_error) < 1e-2);  // brief: < 1 %; root-found to ~1e-13
      // Independent check of the union volume: voxel integration (0.5 % accuracy).
      MassPropertiesOptions vox;
      vox.method = MassMethod::kVoxel;
      MassProperties mp;
      REQUIRE(ComputeMassProperties(s.spheres, 1.0, vox, &mp, &err));
      CHECK(mp.volume_m3 == Approx(s.target_volume_m3).epsilon(5e-3));
      // Overall length 2a for n ≥ 2 (one sphere cannot have both volume and length).
      if (n >= 2) CHECK(s.clump_extents_m.x == Approx(2 * axes.x).epsilon(1e-9));
      // Centre of mass at the origin, long axis x.
      CHECK(Norm(mp.centre_of_mass_m) < 1e-3 * axes.x);
    }
  }
}

TEST_CASE("clump shapes: aspect-ratio error shrinks with the number of spheres", "[clump][unit]") {
  for (const Vec3 axes : {Vec3{1.2, 1, 1}, Vec3{1.5, 1, 1}, Vec3{2, 1, 1}, Vec3{3, 1, 1},
                          Vec3{4, 1, 1}, Vec3{3, 2, 1}}) {
    double previous = INFINITY, first = 0;
    for (int n = 1; n <= 5; ++n) {
      ShapeApproximation s;
      std::string err;
      REQUIRE(ApproximateEllipsoid(axes, n, &s, &err));
      INFO("semi-axes (" << axes.x << ", " << axes.y << ", " << axes.z << "), n = " << n << ", "
                         << s.construction << ", aspect-ratio error " << s.aspect_ratio_error);
      const double e = std::abs(s.aspect_ratio_error);
      CHECK(e <= previous + 1e-9);
      if (n == 1) first = e;
      if (n == 5) {
        CHECK(e < first);
        if (axes.y == axes.z) CHECK(e < 1e-6);  // spheroids: width matched by the tapered chain
      }
      previous = e;
    }
  }
}

TEST_CASE("clump shapes: a spheroid's tapered chain is connected and inside the length",
          "[clump][unit]") {
  ShapeApproximation s;
  std::string err;
  REQUIRE(ApproximateEllipsoid({2, 1, 1}, 5, &s, &err));
  CHECK(s.construction == "tapered");
  CHECK(s.connected);
  for (const auto& sp : s.spheres) {
    CHECK(sp.centre_m.y == 0);
    CHECK(sp.centre_m.z == 0);
    CHECK(sp.radius_m <= 1.0 + 1e-12);  // no sphere wider than the spheroid
    CHECK(std::abs(sp.centre_m.x) + sp.radius_m <= 2.0 + 1e-12);
  }
  // Too few spheres for a long target leave gaps, and that is reported.
  REQUIRE(ApproximateEllipsoid({4, 1, 1}, 2, &s, &err));
  CHECK_FALSE(s.connected);
  // A sphere target: every sphere is the sphere.
  REQUIRE(ApproximateEllipsoid({1, 1, 1}, 4, &s, &err));
  for (const auto& sp : s.spheres) CHECK(sp.radius_m == Approx(1.0).epsilon(1e-9));
}

TEST_CASE("clump shapes: invalid ellipsoid requests are rejected", "[clump][unit]") {
  ShapeApproximation s;
  std::string err;
  CHECK_FALSE(ApproximateEllipsoid({2, 1, 1}, 0, &s, &err));
  CHECK_THAT(err, Catch::Contains("n_spheres = 0 must be in 1..5"));
  CHECK_FALSE(ApproximateEllipsoid({2, 1, 1}, 6, &s, &err));
  CHECK_FALSE(ApproximateEllipsoid({1, 2, 1}, 3, &s, &err));
  CHECK_THAT(err, Catch::Contains("a >= b >= c > 0"));
  CHECK_FALSE(ApproximateEllipsoid({2, 1, 0}, 3, &s, &err));
  CHECK_FALSE(ApproximateEllipsoid({2, 1, std::nan("")}, 3, &s, &err));
}

TEST_CASE("mesh: unit cube mass properties are analytic", "[clump][unit]") {
  // Cube of side s: V = s³, centroid at the centre, I = m s²/6 about every centroidal axis.
  const double rho = 7.0;
  const std::vector<Triangle> cube = Box({0, 0, 0}, {1, 1, 1});
  MeshMassProperties m;
  std::string err;
  REQUIRE(ComputeMeshMassProperties(cube, rho, &m, &err));
  CHECK_FALSE(m.inverted);
  CHECK(m.volume_m3 == Approx(1.0).epsilon(1e-15));
  CHECK(m.mass_kg == Approx(rho).epsilon(1e-15));
  CHECK(Norm(m.centroid_m - Vec3{0.5, 0.5, 0.5}) < 1e-15);
  CHECK((m.inertia_kg_m2 - rho / 6.0 * Eigen::Matrix3d::Identity()).norm() < 1e-14);
  // Rotated and shifted: same volume and principal moments, centroid moves with the cube.
  const Quaternion q = Quaternion::FromAxisAngle({1, 2, 3}, 0.8);
  const Vec3 shift{10, -3, 2};
  REQUIRE(ComputeMeshMassProperties(Transformed(cube, q, shift), rho, &m, &err));
  CHECK(m.volume_m3 == Approx(1.0).epsilon(1e-13));
  CHECK(Norm(m.centroid_m - (shift + Rotate(q, {0.5, 0.5, 0.5}))) < 1e-13);
  for (int a = 0; a < 3; ++a) CHECK(m.principal_inertia_kg_m2[a] == Approx(rho / 6).epsilon(1e-12));
  // Inverted orientation is detected and corrected.
  std::vector<Triangle> flipped = cube;
  for (auto& t : flipped) std::swap(t[1], t[2]);
  REQUIRE(ComputeMeshMassProperties(flipped, rho, &m, &err));
  CHECK(m.inverted);
  CHECK(m.volume_m3 == Approx(1.0).epsilon(1e-15));
  CHECK((m.inertia_kg_m2 - rho / 6.0 * Eigen::Matrix3d::Identity()).norm() < 1e-14);
}

TEST_CASE("mesh: cuboid principal frame and equivalent ellipsoid", "[clump][unit]") {
  // Cuboid 3 × 1 × 0.5: I_x = m(1² + 0.5²)/12 etc.; the inertia-equivalent ellipsoid has
  // semi-axes ∝ (3, 1, 0.5) because a² = 5(I2 + I3 − I1)/(2m) = 5 L²/12.
  const Quaternion q = Quaternion::FromAxisAngle({-1, 0.5, 2}, 1.1);
  const Vec3 shift{0.2, 0.3, -0.4};
  const std::vector<Triangle> box =
      Transformed(Box({-1.5, -0.5, -0.25}, {1.5, 0.5, 0.25}), q, shift);
  MeshMassProperties m;
  std::string err;
  REQUIRE(ComputeMeshMassProperties(box, 1.0, &m, &err));
  const double mass = 1.5;
  CHECK(m.volume_m3 == Approx(1.5).epsilon(1e-13));
  CHECK(Norm(m.centroid_m - shift) < 1e-13);
  CHECK(m.principal_inertia_kg_m2.x == Approx(mass * (1 + 0.25) / 12).epsilon(1e-12));
  CHECK(m.principal_inertia_kg_m2.y == Approx(mass * (9 + 0.25) / 12).epsilon(1e-12));
  CHECK(m.principal_inertia_kg_m2.z == Approx(mass * (9 + 1) / 12).epsilon(1e-12));
  // Principal axis 1 is the long edge.
  const Vec3 long_axis = Rotate(m.mesh_from_principal, {1, 0, 0});
  CHECK(std::abs(Dot(long_axis, Rotate(q, {1, 0, 0}))) == Approx(1.0).epsilon(1e-12));
  CHECK(m.principal_extents_m.x == Approx(3.0).epsilon(1e-12));
  CHECK(m.principal_extents_m.y == Approx(1.0).epsilon(1e-12));
  CHECK(m.principal_extents_m.z == Approx(0.5).epsilon(1e-12));
  const Vec3 e = m.equivalent_semi_axes_m;
  CHECK(e.x / e.y == Approx(3.0).epsilon(1e-12));
  CHECK(e.y / e.z == Approx(2.0).epsilon(1e-12));
  CHECK(4.0 / 3.0 * kPi * e.x * e.y * e.z == Approx(1.5).epsilon(1e-12));
}

TEST_CASE("mesh: tessellated sphere converges to the analytic sphere", "[clump][physics]") {
  // The icosphere is inscribed in the sphere of radius R and contains the ball of its inscribed
  // radius r_in, so V ∈ [4/3 π r_in³, 4/3 π R³] and I ∈ [8/15 π ρ r_in⁵, 8/15 π ρ R⁵] (solid
  // sphere I = (2/5) m R²). The error is second order in the edge length: ~4× smaller per level.
  const double big_r = 2.0;
  const Vec3 c{1, -1, 0.5};
  double previous_error = INFINITY;
  for (int level = 2; level <= 5; ++level) {
    const auto mesh = Icosphere(big_r, c, level);
    MeshMassProperties m;
    std::string err;
    REQUIRE(ComputeMeshMassProperties(mesh, 1.0, &m, &err));
    const double r_in = InscribedRadius(mesh, c);
    const double v_sphere = 4.0 / 3.0 * kPi * std::pow(big_r, 3);
    INFO("level " << level << ", " << mesh.size() << " triangles, V = " << m.volume_m3);
    CHECK(m.volume_m3 <= v_sphere);
    CHECK(m.volume_m3 >= 4.0 / 3.0 * kPi * std::pow(r_in, 3));
    CHECK(Norm(m.centroid_m - c) < 1e-13);
    for (int a = 0; a < 3; ++a) {
      CHECK(m.principal_inertia_kg_m2[a] <= 8.0 / 15.0 * kPi * std::pow(big_r, 5));
      CHECK(m.principal_inertia_kg_m2[a] >= 8.0 / 15.0 * kPi * std::pow(r_in, 5));
    }
    // Icosahedral symmetry makes the inertia isotropic.
    CHECK(m.principal_inertia_kg_m2.z / m.principal_inertia_kg_m2.x - 1 < 1e-12);
    const double error = 1 - m.volume_m3 / v_sphere;
    CHECK(error < previous_error / 3.5);
    previous_error = error;
    if (level == 5) CHECK(error < 1e-3);  // 20480 triangles
  }
}

TEST_CASE("mesh: open or degenerate meshes are rejected", "[clump][unit]") {
  std::vector<Triangle> cube = Box({0, 0, 0}, {1, 1, 1});
  MeshMassProperties m;
  std::string err;
  CHECK_FALSE(ComputeMeshMassProperties({}, 1.0, &m, &err));
  CHECK_THAT(err, Catch::Contains("empty"));
  CHECK_FALSE(ComputeMeshMassProperties(cube, 0.0, &m, &err));
  CHECK_THAT(err, Catch::Contains("density_kg_m3 = 0"));
  std::vector<Triangle> open(cube.begin(), cube.end() - 1);
  CHECK_FALSE(ComputeMeshMassProperties(open, 1.0, &m, &err));
  CHECK_THAT(err, Catch::Contains("not closed"));
  cube[3][1].x = std::nan("");
  CHECK_FALSE(ComputeMeshMassProperties(cube, 1.0, &m, &err));
  CHECK_THAT(err, Catch::Contains("triangles[3] has a non-finite vertex"));
}

TEST_CASE("mesh: STL shapes approximated by n spheres report errors against the mesh",
          "[clump][unit]") {
  // Box 3 × 1.2 × 1 (distinct moments, so its principal frame is unique; L/S = 3), rotated. The
  // equivalent ellipsoid keeps the box's ratios, semi-axes ∝ (3, 1.2, 1); an axisymmetric chain
  // can only match its mean width √(1.2·1), so L/S converges to 3/√1.2: error √(1/1.2) − 1.
  const auto box = Transformed(Box({0, 0, 0}, {3, 1.2, 1}),
                               Quaternion::FromAxisAngle({1, 1, 0}, 0.4), {5, 5, 5});
  double previous = INFINITY;
  for (int n = 1; n <= 5; ++n) {
    MeshApproximation a;
    std::string err;
    REQUIRE(ApproximateMesh(box, n, &a, &err));
    INFO("n = " << n << ", " << a.shape.construction << ", aspect error "
                << a.shape.aspect_ratio_error);
    CHECK(a.shape.target_volume_m3 == Approx(3.6).epsilon(1e-12));
    CHECK(std::abs(a.shape.volume_error) < 1e-2);
    CHECK(a.shape.target_ratios.long_over_short == Approx(3.0).epsilon(1e-12));
    CHECK(std::abs(a.shape.aspect_ratio_error) <= previous + 1e-9);
    previous = std::abs(a.shape.aspect_ratio_error);
  }
  CHECK(previous == Approx(1 - std::sqrt(1 / 1.2)).epsilon(1e-6));
  // A tessellated sphere becomes spheres of the mesh's volume with aspect ratio 1. The mesh's own
  // bounding box (along arbitrary principal axes: the inertia is isotropic) lies between the
  // inscribed and circumscribed balls, so its L/S is at most R / r_in.
  MeshApproximation s;
  std::string err;
  const auto ball = Icosphere(1.0, {0, 0, 0}, 4);
  REQUIRE(ApproximateMesh(ball, 3, &s, &err));
  CHECK(std::abs(s.shape.volume_error) < 1e-9);
  CHECK(s.shape.clump_ratios.long_over_short == Approx(1.0).epsilon(1e-6));
  CHECK(std::abs(s.shape.aspect_ratio_error) <= 1.0 / InscribedRadius(ball, {0, 0, 0}) - 1);
}
