// TriangleMesh: topology, and sphere contacts without double counting on flat meshes, at
// convex and concave edges and corners. The reference for a flat mesh is the analytic plane
// contact (normal = plane normal, overlap = R − height); brute-force checks on convex polyhedra
// and of the grid are in triangle_mesh_convex_test.cc.
#include "core/walls/triangle_mesh.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <optional>
#include <random>
#include <vector>

#include "tests/core/walls/mesh_test_support.h"

using namespace demcal::core;
using namespace demcal::core::mesh_test;

namespace {

// A rigid motion: rotation by `angle` about `axis`, then translation.
struct Motion {
  Vec3 axis{0, 0, 1};
  double angle = 0;
  Vec3 shift;
  Vec3 Rotate(const Vec3& p) const {  // Rodrigues
    const Vec3 k = Unit(axis);
    return std::cos(angle) * p + std::sin(angle) * Cross(k, p) +
           (1 - std::cos(angle)) * Dot(k, p) * k;
  }
  Vec3 operator()(const Vec3& p) const { return Rotate(p) + shift; }
};

// An n × n plate of squares of side `h` in the z = 0 plane (then moved), each split on a
// diagonal; `alternate` flips the diagonal in a checkerboard.
void Plate(int n, double h, bool alternate, const Motion& m, std::vector<Vec3>* v, Tris* t) {
  auto id = [n](int i, int j) { return static_cast<int32_t>(j * (n + 1) + i); };
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) v->push_back(m(Vec3{i * h, j * h, 0}));
  }
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const int32_t a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      if (alternate && (i + j) % 2) {
        t->push_back({a, b, d}), t->push_back({b, c, d});
      } else {
        t->push_back({a, b, c}), t->push_back({a, c, d});
      }
    }
  }
}

// An icosahedron subdivided `levels` times, projected onto the unit sphere (convex, outward).
void CheckPlaneContact(const TriangleMesh& mesh, const Vec3& centre, double radius,
                       const Vec3& plane_point, const Vec3& plane_normal, uint64_t* key,
                       std::optional<MeshFeatureKind> kind = MeshFeatureKind::kFace) {
  std::vector<MeshContact> contacts;
  mesh.SphereContacts(centre, radius, contacts);
  INFO("centre " << centre.x << " " << centre.y << " " << centre.z);
  REQUIRE(contacts.size() == 1);
  const MeshContact& m = contacts[0];
  CHECK(Norm(m.normal - plane_normal) < 1e-12);
  CHECK(std::abs(m.overlap_m - (radius - Dot(centre - plane_point, plane_normal))) < 1e-12);
  if (kind) CHECK(m.kind == *kind);
  if (*key == ~uint64_t{0}) *key = m.Key();
  CHECK(m.Key() == *key);
  CheckWellFormed(contacts, centre, radius);
}

}  // namespace

TEST_CASE("welding a cube soup gives 8 vertices, 18 edges, 6 planar patches, closed",
          "[unit][geometry]") {
  const std::vector<Vec3> v = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                               {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  const Tris t = {{0, 3, 2}, {0, 2, 1}, {4, 5, 6}, {4, 6, 7}, {0, 1, 5}, {0, 5, 4},
                  {3, 7, 6}, {3, 6, 2}, {0, 4, 7}, {0, 7, 3}, {1, 2, 6}, {1, 6, 5}};
  const TriangleMesh mesh = Make(v, t);
  CHECK(mesh.NumVertices() == 8);
  CHECK(mesh.NumTriangles() == 12);
  CHECK(mesh.NumEdges() == 18);
  CHECK(mesh.NumPatches() == 6);
  CHECK(mesh.IsClosed());
  CHECK(mesh.SignedVolume() == Approx(1.0).epsilon(1e-14));
  CHECK(mesh.Area() == Approx(6.0).epsilon(1e-14));
  for (int32_t e = 0; e < static_cast<int32_t>(mesh.NumEdges()); ++e) {
    CHECK(mesh.EdgeTriangles(e).size() == 2);
  }
}

TEST_CASE("a sphere sliding across the diagonal of a split square feels one plane contact",
          "[unit][geometry]") {
  for (const Motion& motion : {Motion{}, Motion{{1, -2, 0.5}, 0.7, {0.3, -1.1, 2.0}}}) {
    std::vector<Vec3> v = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    for (Vec3& x : v) x = motion(x);
    const TriangleMesh mesh = Make(v, {{0, 1, 2}, {0, 2, 3}});
    const Vec3 n = motion.Rotate({0, 0, 1}), origin = motion({0, 0, 0});
    const double radius = 0.1, height = 0.07;
    uint64_t key = ~uint64_t{0};
    auto at = [&](double x, double y) { return motion(Vec3{x, y, 0}) + height * n; };
    // Across the shared edge, through its exact midpoint.
    for (int k = 0; k <= 200; ++k) {
      const double s = k / 200.0;
      CheckPlaneContact(mesh, at(0.8 - 0.6 * s, 0.2 + 0.6 * s), radius, origin, n, &key);
    }
    CheckPlaneContact(mesh, at(0.5, 0.5), radius, origin, n, &key);
    // Along the shared edge, from one shared vertex to the other.
    for (int k = 1; k < 100; ++k) {
      CheckPlaneContact(mesh, at(k / 100.0, k / 100.0), radius, origin, n, &key);
    }
    // Exactly over the shared vertices (corners of the square: a vertex contact, or a face
    // contact if rounding puts the centre just inside, with the same plane normal and overlap).
    for (const Vec3& corner : {v[0], v[2]}) {
      uint64_t corner_key = ~uint64_t{0};
      CheckPlaneContact(mesh, corner + height * n, radius, origin, n, &corner_key, std::nullopt);
    }
    // From below (meshes are two-sided).
    uint64_t below_key = ~uint64_t{0};
    CheckPlaneContact(mesh, motion(Vec3{0.5, 0.5, 0}) - height * n, radius, origin, -n, &below_key);
  }
}

TEST_CASE("a sphere rolling over a large flat plate feels one plane contact everywhere",
          "[unit][geometry]") {
  for (const bool alternate : {false, true}) {
    for (const Motion& motion : {Motion{}, Motion{{0.3, 1, -0.2}, 1.1, {-4, 2, 7}}}) {
      const int n = 40;
      const double side = 0.025;  // a 1 m plate of 3200 triangles
      std::vector<Vec3> v;
      Tris t;
      Plate(n, side, alternate, motion, &v, &t);
      const TriangleMesh mesh = Make(v, t);
      REQUIRE(mesh.NumTriangles() == 3200);
      REQUIRE(mesh.NumPatches() == 1);
      const Vec3 nz = motion.Rotate({0, 0, 1}), origin = motion({0, 0, 0});
      // Radii smaller than a triangle and spanning many triangles.
      for (const double radius : {0.01, 0.2}) {
        const double height = 0.8 * radius;
        uint64_t key = ~uint64_t{0};
        auto at = [&](const Vec3& p) { return motion(p) + height * nz; };
        // A slanted path crossing edges at arbitrary points.
        for (int k = 0; k <= 500; ++k) {
          const double s = k / 500.0;
          CheckPlaneContact(mesh, at({0.25 + 0.5 * s, 0.3 + 0.41 * s, 0}), radius, origin, nz,
                            &key);
        }
        // Exactly over interior vertices and the midpoints of interior edges.
        for (int j = 10; j <= 30; j += 3) {
          for (int i = 10; i <= 30; i += 2) {
            const Vec3 p = v[j * (n + 1) + i], right = v[j * (n + 1) + i + 1];
            const Vec3 up = v[(j + 1) * (n + 1) + i], diag = v[(j + 1) * (n + 1) + i + 1];
            for (const Vec3& q :
                 {p, 0.5 * (p + right), 0.5 * (p + up), 0.5 * (p + diag), 0.5 * (right + up)}) {
              CheckPlaneContact(mesh, q + height * nz, radius, origin, nz, &key);
            }
          }
        }
      }
    }
  }
}

TEST_CASE("a convex 90-degree edge gives one edge contact beyond both faces", "[unit][geometry]") {
  // Face A: z = 0 for x in [-1, 0] (normal +z); face B: x = 0 for z in [-1, 0] (normal +x).
  const std::vector<Vec3> v = {{-1, 0, 0}, {0, 0, 0},  {0, 1, 0},
                               {-1, 1, 0}, {0, 0, -1}, {0, 1, -1}};
  const TriangleMesh mesh = Make(v, {{0, 1, 2}, {0, 2, 3}, {1, 4, 5}, {1, 5, 2}});
  REQUIRE(mesh.NumPatches() == 2);
  const double radius = 0.1;
  std::vector<MeshContact> contacts;

  mesh.SphereContacts({0.05, 0.5, 0.05}, radius, contacts);
  REQUIRE(contacts.size() == 1);
  CHECK(contacts[0].kind == MeshFeatureKind::kEdge);
  CHECK(Norm(contacts[0].normal - Unit(Vec3{1, 0, 1})) < 1e-12);
  CHECK(contacts[0].overlap_m == Approx(radius - 0.05 * std::sqrt(2.0)).epsilon(1e-12));

  // Rolling around the edge at a fixed distance: one contact, constant overlap, radial normal.
  const double d = 0.07;
  for (int k = 0; k <= 90; ++k) {
    const double th = k * std::numbers::pi / 180;
    for (const double y : {0.0, 0.3, 0.5, 1.0}) {
      const Vec3 c{d * std::sin(th), y, d * std::cos(th)};
      mesh.SphereContacts(c, radius, contacts);
      INFO("angle " << k << " y " << y);
      REQUIRE(contacts.size() == 1);
      CHECK(contacts[0].overlap_m == Approx(radius - d).epsilon(1e-12));
      CHECK(Norm(contacts[0].normal - Vec3{std::sin(th), 0, std::cos(th)}) < 1e-12);
      if (k > 0 && k < 90 && y > 0 && y < 1) CHECK(contacts[0].kind == MeshFeatureKind::kEdge);
      CheckWellFormed(contacts, c, radius);
    }
  }
  // Random centres beyond both faces.
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(0, 1);
  for (int k = 0; k < 2000; ++k) {
    const Vec3 c{0.09 * u(rng), 0.05 + 0.9 * u(rng), 0.09 * u(rng)};
    if (std::hypot(c.x, c.z) >= radius) continue;
    mesh.SphereContacts(c, radius, contacts);
    REQUIRE(contacts.size() == 1);
    CHECK(contacts[0].kind == MeshFeatureKind::kEdge);
    CHECK(Norm(contacts[0].normal - Unit(Vec3{c.x, 0, c.z})) < 1e-12);
  }
  // Over face A only: a face contact.
  mesh.SphereContacts({-0.3, 0.5, 0.05}, radius, contacts);
  REQUIRE(contacts.size() == 1);
  CHECK(contacts[0].kind == MeshFeatureKind::kFace);
  CHECK(Norm(contacts[0].normal - Vec3{0, 0, 1}) < 1e-15);
}

TEST_CASE("inside a box mesh, a corner gives one contact per face", "[unit][geometry]") {
  const std::vector<Vec3> v = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                               {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  const TriangleMesh mesh = Make(v, {{0, 3, 2},
                                     {0, 2, 1},
                                     {4, 5, 6},
                                     {4, 6, 7},
                                     {0, 1, 5},
                                     {0, 5, 4},
                                     {3, 7, 6},
                                     {3, 6, 2},
                                     {0, 4, 7},
                                     {0, 7, 3},
                                     {1, 2, 6},
                                     {1, 6, 5}});
  std::vector<MeshContact> contacts;
  mesh.SphereContacts({0.1, 0.1, 0.1}, 0.15, contacts);
  REQUIRE(contacts.size() == 3);
  Vec3 sum;
  for (const MeshContact& m : contacts) {
    CHECK(m.kind == MeshFeatureKind::kFace);
    CHECK(m.overlap_m == Approx(0.05).epsilon(1e-12));
    sum += m.normal;
  }
  CHECK(Norm(sum - Vec3{1, 1, 1}) < 1e-12);
  mesh.SphereContacts({0.1, 0.5, 0.1}, 0.15, contacts);  // along an inner edge
  CHECK(contacts.size() == 2);
  // Outside: a vertex, an edge and a face (over the face's diagonal) each give one contact.
  mesh.SphereContacts({1.05, 1.05, 1.05}, 0.1, contacts);
  REQUIRE(contacts.size() == 1);
  CHECK(contacts[0].kind == MeshFeatureKind::kVertex);
  CHECK(Norm(contacts[0].normal - Unit(Vec3{1, 1, 1})) < 1e-12);
  mesh.SphereContacts({0.5, 1.05, 1.05}, 0.1, contacts);
  REQUIRE(contacts.size() == 1);
  CHECK(contacts[0].kind == MeshFeatureKind::kEdge);
  mesh.SphereContacts({0.5, 0.5, 1.05}, 0.1, contacts);
  REQUIRE(contacts.size() == 1);
  CHECK(contacts[0].kind == MeshFeatureKind::kFace);
  CHECK(contacts[0].overlap_m == Approx(0.05).epsilon(1e-12));
}

TEST_CASE("a sheet folded back on itself has an edge, not a flat patch", "[unit][geometry]") {
  // Two coplanar triangles on the same side of their shared edge (x = 0): a knife edge.
  const std::vector<Vec3> v = {{0, 0, 0}, {0, 1, 0}, {-1, 0.5, 0}, {-1, 0.6, 0}};
  const TriangleMesh mesh = Make(v, {{0, 1, 2}, {1, 0, 3}});
  CHECK(mesh.NumPatches() == 2);
  std::vector<MeshContact> contacts;
  mesh.SphereContacts({0.05, 0.5, 0}, 0.1, contacts);  // beside the edge, in the plane
  REQUIRE(contacts.size() == 1);
  CHECK(contacts[0].kind == MeshFeatureKind::kEdge);
  CHECK(contacts[0].overlap_m == Approx(0.05).epsilon(1e-12));
  CHECK(Norm(contacts[0].normal - Vec3{1, 0, 0}) < 1e-12);
}

TEST_CASE("a doubled triangle (either winding) is one contact", "[unit][geometry]") {
  const std::vector<Vec3> v = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  const TriangleMesh mesh = Make(v, {{0, 1, 2}, {0, 2, 1}, {0, 1, 2}});
  CHECK(mesh.NumTriangles() == 1);
  CHECK(mesh.DroppedDuplicates() == 2);
  std::vector<MeshContact> contacts;
  for (const Vec3& c : {Vec3{0.2, 0.2, 0.05}, Vec3{0.5, 0.5, 0.05}, Vec3{-0.03, 0.5, 0.05},
                        Vec3{-0.03, -0.03, 0.05}}) {
    mesh.SphereContacts(c, 0.1, contacts);
    CHECK(contacts.size() == 1);
  }
}

TEST_CASE("bad meshes and queries are refused without crashing", "[unit][geometry]") {
  std::string error;
  const std::vector<Vec3> v = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  const Tris out_of_range = {{0, 1, 3}};
  CHECK_FALSE(TriangleMesh::FromIndexed(v, out_of_range, {}, &error));
  CHECK_THAT(error, Catch::Contains("out of range"));
  const Tris repeated = {{0, 1, 1}};
  CHECK_FALSE(TriangleMesh::FromIndexed(v, repeated, {}, &error));
  CHECK_THAT(error, Catch::Contains("degenerate"));
  const std::vector<StlTriangle> tiny = {{{Vec3{0, 0, 0}, Vec3{1e-12, 0, 0}, Vec3{0, 1e-12, 0}}},
                                         {{Vec3{5, 5, 5}, Vec3{6, 5, 5}, Vec3{5, 6, 5}}}};
  // With a 1 mm weld tolerance the first triangle collapses and is dropped.
  const auto welded = TriangleMesh::FromSoup(tiny, {.weld_tolerance_m = 1e-3}, &error);
  REQUIRE(welded);
  CHECK(welded->NumTriangles() == 1);
  CHECK(welded->DroppedDegenerate() == 1);
  CHECK_FALSE(TriangleMesh::FromSoup({}, {}, &error));
  CHECK_FALSE(TriangleMesh::FromSoup(tiny, {.flat_angle_rad = 1}, &error));
  CHECK_THAT(error, Catch::Contains("flat_angle_rad"));
  const std::vector<StlTriangle> nan = {{{Vec3{0, 0, 0}, Vec3{NAN, 0, 0}, Vec3{0, 1, 0}}}};
  CHECK_FALSE(TriangleMesh::FromSoup(nan, {}, &error));

  const TriangleMesh mesh = Make(v, {{0, 1, 2}});
  std::vector<MeshContact> contacts(3);
  mesh.SphereContacts({NAN, 0, 0}, 0.1, contacts);
  CHECK(contacts.empty());
  mesh.SphereContacts({0.2, 0.2, 0}, -1, contacts);
  CHECK(contacts.empty());
  mesh.SphereContacts({50, 50, 50}, 0.1, contacts);  // far outside the grid
  CHECK(contacts.empty());
  mesh.SphereContacts({0.2, 0.2, 0}, 0.1, contacts);  // centre on the surface
  REQUIRE(contacts.size() == 1);
  CHECK(contacts[0].overlap_m == Approx(0.1));
}
