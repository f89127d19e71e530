#pragma once
// Shared helpers of the TriangleMesh tests: building meshes, an icosphere (a convex polyhedron
// with vertices of valence 5 and 6), a brute-force nearest distance, contact sanity checks.
#include <algorithm>
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "core/walls/triangle_mesh.h"
#include "core/walls/wall_geometry.h"

namespace demcal::core::mesh_test {

using Tris = std::vector<std::array<int32_t, 3>>;

inline Vec3 Unit(const Vec3& v) { return v / Norm(v); }

inline TriangleMesh Make(const std::vector<Vec3>& v, const Tris& t,
                         const TriangleMeshOptions& o = {}) {
  std::vector<StlTriangle> soup;
  for (const auto& tri : t) soup.push_back({{v[tri[0]], v[tri[1]], v[tri[2]]}});
  std::string error;
  auto mesh = TriangleMesh::FromSoup(soup, o, &error);
  INFO(error);
  REQUIRE(mesh);
  return std::move(*mesh);
}

// An icosahedron subdivided `levels` times, projected onto the unit sphere (convex, outward).
inline void Icosphere(int levels, std::vector<Vec3>* v, Tris* t) {
  const double p = (1 + std::sqrt(5.0)) / 2;
  *v = {{-1, p, 0},  {1, p, 0},  {-1, -p, 0}, {1, -p, 0}, {0, -1, p},  {0, 1, p},
        {0, -1, -p}, {0, 1, -p}, {p, 0, -1},  {p, 0, 1},  {-p, 0, -1}, {-p, 0, 1}};
  for (Vec3& x : *v) x = Unit(x);
  *t = {{0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
        {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
        {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  for (int l = 0; l < levels; ++l) {
    std::map<std::pair<int32_t, int32_t>, int32_t> mid;
    auto midpoint = [&](int32_t a, int32_t b) {
      const auto key = std::minmax(a, b);
      auto [it, fresh] = mid.try_emplace(key, static_cast<int32_t>(v->size()));
      if (fresh) v->push_back(Unit((*v)[a] + (*v)[b]));
      return it->second;
    };
    Tris next;
    for (const auto& f : *t) {
      const int32_t a = midpoint(f[0], f[1]), b = midpoint(f[1], f[2]), c = midpoint(f[2], f[0]);
      next.insert(next.end(), {{f[0], a, c}, {f[1], b, a}, {f[2], c, b}, {a, b, c}});
    }
    *t = std::move(next);
  }
}

// Brute force: the smallest distance from p to any triangle of the mesh.
inline double BruteDistance(const TriangleMesh& mesh, const Vec3& p) {
  double best = std::numeric_limits<double>::infinity();
  for (int32_t t = 0; t < static_cast<int32_t>(mesh.NumTriangles()); ++t) {
    const auto& c = mesh.TriangleVertices(t);
    const Vec3 x =
        ClosestPointOnTriangle(p, mesh.Vertex(c[0]), mesh.Vertex(c[1]), mesh.Vertex(c[2])).point_m;
    best = std::min(best, Norm(p - x));
  }
  return best;
}

// Every contact is self-consistent: unit normal from the point to the centre, overlap in (0, R].
inline void CheckWellFormed(const std::vector<MeshContact>& contacts, const Vec3& c, double r) {
  for (const MeshContact& m : contacts) {
    CHECK(std::abs(Norm(m.normal) - 1) < 1e-12);
    CHECK(m.overlap_m > 0);
    CHECK(m.overlap_m <= r);
    CHECK(Norm(c - m.point_m - (r - m.overlap_m) * m.normal) < 1e-12);
  }
}

// The contacts along a path over a flat mesh are one plane contact with a constant key.
}  // namespace demcal::core::mesh_test
