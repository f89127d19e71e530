// TriangleMesh::NearTriangles and the near-list SphereContacts a static mesh wall uses between
// neighbour rebuilds (WallContacts): the near list is exactly the triangles within reach (brute
// force), and contacts computed from a list made up to one skin earlier equal the grid query's.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <random>
#include <vector>

#include "core/walls/triangle_mesh.h"
#include "tests/core/walls/mesh_test_support.h"

using namespace demcal::core;
using namespace demcal::core::mesh_test;

namespace {

// A flat annulus of long fan triangles (a silo bottom with an orifice, as bench/pours).
TriangleMesh Annulus(double r_in, double r_out, int segments) {
  std::vector<Vec3> v;
  Tris t;
  for (int s = 0; s < segments; ++s) {
    const double a = 2 * M_PI * s / segments;
    v.push_back({r_in * std::cos(a), r_in * std::sin(a), 0});
    v.push_back({r_out * std::cos(a), r_out * std::sin(a), 0});
  }
  for (int s = 0; s < segments; ++s) {
    const int32_t i0 = 2 * s, o0 = 2 * s + 1, i1 = (2 * s + 2) % (2 * segments),
                  o1 = (2 * s + 3) % (2 * segments);
    t.push_back({i0, o0, o1});
    t.push_back({i0, o1, i1});
  }
  return Make(v, t);
}

std::vector<int32_t> BruteNear(const TriangleMesh& mesh, const Vec3& c, double reach) {
  std::vector<int32_t> near;
  for (int32_t f = 0; f < static_cast<int32_t>(mesh.NumTriangles()); ++f) {
    const auto& k = mesh.TriangleVertices(f);
    const Vec3 x =
        ClosestPointOnTriangle(c, mesh.Vertex(k[0]), mesh.Vertex(k[1]), mesh.Vertex(k[2])).point_m;
    if (Norm(c - x) <= reach) near.push_back(f);
  }
  return near;
}

std::vector<MeshContact> ByKey(std::vector<MeshContact> contacts) {
  std::sort(contacts.begin(), contacts.end(),
            [](const MeshContact& a, const MeshContact& b) { return a.Key() < b.Key(); });
  return contacts;
}

// Random spheres near `mesh`: the near list equals brute force, and the contacts from a list
// made at a point up to `skin` away (with reach radius + skin) equal the grid query's.
void CheckNearAgreesWithGrid(const TriangleMesh& mesh, const Vec3& lo, const Vec3& hi, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<int32_t> near;
  std::vector<MeshContact> from_grid, from_near;
  int touching = 0;
  for (int k = 0; k < 2000; ++k) {
    const Vec3 c{lo.x + (hi.x - lo.x) * u(rng), lo.y + (hi.y - lo.y) * u(rng),
                 lo.z + (hi.z - lo.z) * u(rng)};
    const double radius = 0.001 * (0.8 + 0.4 * u(rng)), skin = 0.5 * radius;
    const Vec3 step = Vec3{u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5};
    const Vec3 then = c + (skin * u(rng)) * step / Norm(step);  // where the list was made
    mesh.NearTriangles(then, radius + skin, near);
    REQUIRE(near == BruteNear(mesh, then, radius + skin));
    mesh.SphereContacts(c, radius, from_grid);
    mesh.SphereContacts(c, radius, near, from_near);
    from_grid = ByKey(from_grid), from_near = ByKey(from_near);
    REQUIRE(from_near.size() == from_grid.size());
    for (size_t m = 0; m < from_grid.size(); ++m) {
      CHECK(from_near[m].Key() == from_grid[m].Key());
      // Coplanar triangles of one patch may differ in the last bit of the plane distance, and
      // the two queries visit them in different orders: equal to rounding.
      CHECK(from_near[m].overlap_m == Approx(from_grid[m].overlap_m).margin(1e-15));
      CHECK(Norm(from_near[m].normal - from_grid[m].normal) < 1e-12);
    }
    touching += !from_grid.empty();
  }
  CHECK(touching > 200);  // the draw exercised contacts, not only misses
}

}  // namespace

TEST_CASE("near triangles give the grid's contacts on a fan-triangulated silo bottom",
          "[unit][geometry]") {
  const TriangleMesh bottom = Annulus(0.008, 0.03, 64);
  // Spheres resting on, sinking into and hovering over the annulus, and in the orifice.
  CheckNearAgreesWithGrid(bottom, {-0.032, -0.032, -0.0015}, {0.032, 0.032, 0.003}, 5);
  std::vector<int32_t> near;
  bottom.NearTriangles({0.02, 0, 0.001}, 0.0015, near);
  CHECK(near.size() <= 4);  // a resting sphere sees its own few triangles of 128
  bottom.NearTriangles({0.02, 0, 0.01}, 0.0015, near);
  CHECK(near.empty());
}

TEST_CASE("near triangles give the grid's contacts on a convex mesh, translated", "[unit][geometry]") {
  std::vector<Vec3> v;
  Tris t;
  Icosphere(3, &v, &t);
  for (Vec3& x : v) x = 0.01 * x;  // radius 10 mm, edges ~1 mm: spheres touch several features
  TriangleMesh ball = Make(v, t);
  ball.Translate({0.003, -0.002, 0.001});
  CheckNearAgreesWithGrid(ball, {-0.01, -0.015, -0.01}, {0.016, 0.011, 0.014}, 6);
}
