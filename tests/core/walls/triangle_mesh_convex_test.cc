// TriangleMesh against brute force: outside a convex polyhedron there is exactly one contact
// and its overlap is R − (distance to the nearest triangle, over all triangles), also for centres
// placed exactly on the boundaries between feature regions; the grid broad phase returns exactly
// the triangles a brute-force bounding-box scan finds; translation moves contacts rigidly.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <random>
#include <vector>

#include "core/walls/triangle_mesh.h"
#include "tests/core/walls/mesh_test_support.h"

using namespace demcal::core;
using namespace demcal::core::mesh_test;

TEST_CASE("outside a convex polyhedron there is exactly one contact, the nearest point",
          "[unit][geometry]") {
  std::vector<Vec3> v;
  Tris t;
  Icosphere(3, &v, &t);
  const TriangleMesh mesh = Make(v, t);
  REQUIRE(mesh.NumTriangles() == 1280);
  REQUIRE(mesh.IsClosed());
  std::mt19937_64 rng(17);
  std::normal_distribution<double> g;
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<MeshContact> contacts;
  int touching = 0;
  for (int k = 0; k < 3000; ++k) {
    const Vec3 c = (0.97 + 0.15 * u(rng)) * Unit(Vec3{g(rng), g(rng), g(rng)});
    const double radius = 0.02 + 0.2 * u(rng);
    bool outside = false;  // in front of some face (normals oriented away from the origin)
    for (int32_t f = 0; f < static_cast<int32_t>(mesh.NumTriangles()); ++f) {
      const Vec3 v0 = mesh.Vertex(mesh.TriangleVertices(f)[0]), n = mesh.TriangleNormal(f);
      outside = outside || Dot(c - v0, n) * Dot(v0, n) > 0;
    }
    const double nearest = BruteDistance(mesh, c);
    mesh.SphereContacts(c, radius, contacts);
    INFO("query " << k);
    CheckWellFormed(contacts, c, radius);
    double deepest = 0;
    for (const MeshContact& m : contacts) deepest = std::max(deepest, m.overlap_m);
    if (nearest < radius) {
      CHECK(deepest == Approx(radius - nearest).margin(1e-12));
      if (outside) CHECK(contacts.size() == 1);
      touching += outside;
    } else {
      CHECK(contacts.empty());
    }
  }
  CHECK(touching > 1000);
}

TEST_CASE("on the boundaries between Voronoi regions of a convex mesh there is one contact",
          "[unit][geometry]") {
  // Centres placed exactly where a face region meets an edge or vertex region (and inside edge
  // and vertex regions): rounding must neither lose the contact nor report it twice.
  std::vector<Vec3> v;
  Tris t;
  Icosphere(2, &v, &t);
  const TriangleMesh mesh = Make(v, t);
  const double radius = 0.1, gap = 0.05;
  std::vector<MeshContact> contacts;
  auto check_one = [&](const Vec3& c, const char* what) {
    mesh.SphereContacts(c, radius, contacts);
    INFO(what << " at " << c.x << " " << c.y << " " << c.z);
    REQUIRE(contacts.size() == 1);
    CHECK(contacts[0].overlap_m == Approx(radius - gap).margin(1e-12));
  };
  for (int32_t f = 0; f < static_cast<int32_t>(mesh.NumTriangles()); ++f) {
    const auto& c = mesh.TriangleVertices(f);
    Vec3 n = mesh.TriangleNormal(f);
    if (Dot(n, mesh.Vertex(c[0])) < 0) n = -n;  // outward
    for (int k = 0; k < 3; ++k) {
      const Vec3 a = mesh.Vertex(c[k]), b = mesh.Vertex(c[(k + 1) % 3]);
      check_one(a + gap * n, "corner along the face normal");
      check_one(0.5 * (a + b) + gap * n, "edge midpoint along the face normal");
      check_one(0.3 * a + 0.7 * b + gap * n, "edge point along the face normal");
    }
  }
  for (int32_t e = 0; e < static_cast<int32_t>(mesh.NumEdges()); ++e) {
    const auto tris = mesh.EdgeTriangles(e);
    const Vec3 mid =
        0.5 * (mesh.Vertex(mesh.EdgeVertices(e)[0]) + mesh.Vertex(mesh.EdgeVertices(e)[1]));
    Vec3 n = mesh.TriangleNormal(tris[0]) + mesh.TriangleNormal(tris[1]);
    if (Dot(n, mid) < 0) n = -n;
    check_one(mid + gap * Unit(n), "edge midpoint along the edge bisector");
  }
  for (int32_t i = 0; i < static_cast<int32_t>(mesh.NumVertices()); ++i) {
    check_one(mesh.Vertex(i) * (1 + gap), "vertex along the radius");
  }
}

TEST_CASE("grid broad phase matches a brute-force box scan on a random soup", "[unit][geometry]") {
  std::mt19937_64 rng(23);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<StlTriangle> soup;
  while (soup.size() < 3000) {
    const Vec3 a{u(rng), u(rng), 0.3 * u(rng)};
    StlTriangle tri{
        {a, a + 0.05 * Vec3{u(rng), u(rng), u(rng)}, a + 0.05 * Vec3{u(rng), u(rng), u(rng)}}};
    if (!IsDegenerateTriangle(tri, 1e-3)) soup.push_back(tri);
  }
  std::string error;
  const auto mesh = TriangleMesh::FromSoup(soup, {}, &error);
  REQUIRE(mesh);
  std::vector<int32_t> got, want;
  std::vector<MeshContact> contacts;
  for (int k = 0; k < 500; ++k) {
    const Vec3 c{1.4 * u(rng) - 0.2, 1.4 * u(rng) - 0.2, 0.7 * u(rng) - 0.2};
    const double radius = 0.005 + 0.1 * u(rng);
    mesh->CandidateTriangles(c, radius, got);
    want.clear();
    for (int32_t f = 0; f < static_cast<int32_t>(mesh->NumTriangles()); ++f) {
      bool overlaps = true;
      for (int a = 0; a < 3; ++a) {
        double lo = 1e300, hi = -1e300;
        for (int32_t x : mesh->TriangleVertices(f)) {
          lo = std::min(lo, mesh->Vertex(x)[a]), hi = std::max(hi, mesh->Vertex(x)[a]);
        }
        overlaps = overlaps && hi >= c[a] - radius && lo <= c[a] + radius;
      }
      if (overlaps) want.push_back(f);
    }
    REQUIRE(got == want);
    // Contacts exist exactly when some triangle is within reach; the deepest is the nearest.
    const double nearest = BruteDistance(*mesh, c);
    mesh->SphereContacts(c, radius, contacts);
    CheckWellFormed(contacts, c, radius);
    CHECK(contacts.empty() == (nearest >= radius));
    double deepest = 0;
    for (const MeshContact& m : contacts) deepest = std::max(deepest, m.overlap_m);
    if (!contacts.empty()) CHECK(deepest == Approx(radius - nearest).margin(1e-12));
  }
  // A small sphere looks at a small part of the mesh.
  mesh->CandidateTriangles({0.5, 0.5, 0.15}, 0.01, got);
  CHECK(got.size() < mesh->NumTriangles() / 50);
}

TEST_CASE("translating a mesh moves its contacts and keeps their keys", "[unit][geometry]") {
  std::vector<Vec3> v;
  Tris t;
  Icosphere(2, &v, &t);
  TriangleMesh mesh = Make(v, t);
  const Vec3 shift{0.3, -2.0, 1.25};
  std::vector<MeshContact> before, after;
  std::mt19937_64 rng(2);
  std::normal_distribution<double> g;
  const double volume = mesh.SignedVolume();
  std::vector<Vec3> centres;
  for (int k = 0; k < 200; ++k) centres.push_back(1.05 * Unit(Vec3{g(rng), g(rng), g(rng)}));
  std::vector<std::vector<MeshContact>> reference;
  for (const Vec3& c : centres) {
    mesh.SphereContacts(c, 0.1, before);
    std::sort(before.begin(), before.end(),
              [](const MeshContact& a, const MeshContact& b) { return a.Key() < b.Key(); });
    reference.push_back(before);
  }
  mesh.Translate(shift);
  CHECK(Norm(mesh.offset_m() - shift) == 0);
  CHECK(Norm(mesh.Vertex(0) - (v[0] + shift)) < 1e-15);
  CHECK(mesh.SignedVolume() == Approx(volume).epsilon(1e-12));
  for (size_t k = 0; k < centres.size(); ++k) {
    mesh.SphereContacts(centres[k] + shift, 0.1, after);
    std::sort(after.begin(), after.end(),
              [](const MeshContact& a, const MeshContact& b) { return a.Key() < b.Key(); });
    REQUIRE(after.size() == reference[k].size());
    for (size_t i = 0; i < after.size(); ++i) {
      CHECK(after[i].Key() == reference[k][i].Key());
      CHECK(after[i].overlap_m == Approx(reference[k][i].overlap_m).margin(1e-12));
      CHECK(Norm(after[i].point_m - shift - reference[k][i].point_m) < 1e-12);
    }
  }
}
