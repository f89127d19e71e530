// TriangleMesh construction: welding, topology (edges, adjacency), planar patches, the grid.
// The contact query is in triangle_mesh_contacts.cc.
#include "core/walls/triangle_mesh.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <set>
#include <tuple>
#include <unordered_map>

namespace demcal::core {
namespace {

constexpr double kDegenerateTolerance = 1e-10;  // as StlReadOptions::degenerate_tolerance

bool Fail(std::string* error, const std::string& message) {
  if (error) *error = message;
  return false;
}

uint64_t CellHash(int64_t x, int64_t y, int64_t z) {
  uint64_t h = static_cast<uint64_t>(x) * 0x9E3779B97F4A7C15ull;
  h ^= static_cast<uint64_t>(y) * 0xC2B2AE3D27D4EB4Full + (h << 6) + (h >> 2);
  h ^= static_cast<uint64_t>(z) * 0x165667B19E3779F9ull + (h << 6) + (h >> 2);
  return h;
}

// Merges points closer than `tol` (to the first-seen representative). Returns the index of
// each point's representative in `unique`.
std::vector<int32_t> Weld(const std::vector<Vec3>& points, double tol, std::vector<Vec3>* unique) {
  std::unordered_map<uint64_t, std::vector<int32_t>> cells;
  cells.reserve(points.size());
  std::vector<int32_t> index(points.size());
  const double inv = 1.0 / tol, tol2 = tol * tol;
  for (size_t i = 0; i < points.size(); ++i) {
    const Vec3& p = points[i];
    const int64_t cx = static_cast<int64_t>(std::floor(p.x * inv));
    const int64_t cy = static_cast<int64_t>(std::floor(p.y * inv));
    const int64_t cz = static_cast<int64_t>(std::floor(p.z * inv));
    int32_t found = -1;
    for (int64_t dz = -1; dz <= 1; ++dz) {
      for (int64_t dy = -1; dy <= 1; ++dy) {
        for (int64_t dx = -1; dx <= 1; ++dx) {
          const auto it = cells.find(CellHash(cx + dx, cy + dy, cz + dz));
          if (it == cells.end()) continue;
          for (int32_t u : it->second) {
            if (Norm2((*unique)[u] - p) <= tol2 && (found < 0 || u < found)) found = u;
          }
        }
      }
    }
    if (found < 0) {
      found = static_cast<int32_t>(unique->size());
      unique->push_back(p);
      cells[CellHash(cx, cy, cz)].push_back(found);
    }
    index[i] = found;
  }
  return index;
}

}  // namespace

bool TriangleMeshOptions::IsValid(std::string* error) const {
  if (!(weld_tolerance_m >= 0) || !std::isfinite(weld_tolerance_m)) {
    return Fail(error, "TriangleMeshOptions::weld_tolerance_m must be finite and >= 0");
  }
  if (!(grid_cell_m >= 0) || !std::isfinite(grid_cell_m)) {
    return Fail(error, "TriangleMeshOptions::grid_cell_m must be finite and >= 0");
  }
  if (!(flat_angle_rad >= 0 && flat_angle_rad < 0.1)) {
    return Fail(error, "TriangleMeshOptions::flat_angle_rad must be in [0, 0.1)");
  }
  return true;
}

std::optional<TriangleMesh> TriangleMesh::FromSoup(std::span<const StlTriangle> soup,
                                                   const TriangleMeshOptions& options,
                                                   std::string* error) {
  if (!options.IsValid(error)) return std::nullopt;
  if (soup.empty()) {
    Fail(error, "triangle mesh: no triangles");
    return std::nullopt;
  }
  std::vector<Vec3> corners;
  corners.reserve(3 * soup.size());
  Vec3 lo = soup[0].v[0], hi = lo;
  for (const StlTriangle& t : soup) {
    for (const Vec3& p : t.v) {
      if (!IsFinite(p)) {
        Fail(error, "triangle mesh: non-finite vertex coordinate");
        return std::nullopt;
      }
      corners.push_back(p);
      for (int a = 0; a < 3; ++a) {
        lo[a] = std::min(lo[a], p[a]);
        hi[a] = std::max(hi[a], p[a]);
      }
    }
  }
  const double diagonal = Norm(hi - lo);
  double tol = options.weld_tolerance_m > 0 ? options.weld_tolerance_m : 1e-9 * diagonal;
  tol = std::max(tol, 1e-15 * std::max(diagonal, Norm(hi) + Norm(lo)));
  if (!(tol > 0)) tol = 1e-300;  // every corner is the same point: all degenerate below
  std::vector<Vec3> unique;
  const std::vector<int32_t> index = Weld(corners, tol, &unique);
  std::vector<std::array<int32_t, 3>> triangles(soup.size());
  for (size_t t = 0; t < soup.size(); ++t) {
    triangles[t] = {index[3 * t], index[3 * t + 1], index[3 * t + 2]};
  }
  return FromIndexed(std::move(unique), triangles, options, error);
}

std::optional<TriangleMesh> TriangleMesh::FromIndexed(
    std::vector<Vec3> vertices, std::span<const std::array<int32_t, 3>> triangles,
    const TriangleMeshOptions& options, std::string* error) {
  if (!options.IsValid(error)) return std::nullopt;
  TriangleMesh mesh;
  for (const Vec3& p : vertices) {
    if (!IsFinite(p)) {
      Fail(error, "triangle mesh: non-finite vertex coordinate");
      return std::nullopt;
    }
  }
  const auto n = static_cast<int64_t>(vertices.size());
  std::set<std::array<int32_t, 3>> seen;  // vertex sets already used: repeats are dropped
  for (const auto& t : triangles) {
    for (int32_t v : t) {
      if (v < 0 || v >= n) {
        Fail(error, "triangle mesh: vertex index " + std::to_string(v) + " out of range [0, " +
                        std::to_string(n) + ")");
        return std::nullopt;
      }
    }
    const StlTriangle corners{{vertices[t[0]], vertices[t[1]], vertices[t[2]]}};
    if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0] ||
        IsDegenerateTriangle(corners, kDegenerateTolerance)) {
      ++mesh.dropped_degenerate_;
      continue;
    }
    std::array<int32_t, 3> sorted = t;
    std::sort(sorted.begin(), sorted.end());
    if (!seen.insert(sorted).second) {
      ++mesh.dropped_duplicate_;
      continue;
    }
    mesh.tri_vertices_.push_back(t);
  }
  if (mesh.tri_vertices_.empty()) {
    Fail(error, "triangle mesh: all " + std::to_string(triangles.size()) +
                    " triangles are degenerate (zero area after welding)");
    return std::nullopt;
  }
  mesh.vertices_ = std::move(vertices);
  if (!mesh.Build(options, error)) return std::nullopt;
  return mesh;
}

bool TriangleMesh::Build(const TriangleMeshOptions& options, std::string* error) {
  const size_t nt = tri_vertices_.size();
  tri_.resize(nt);
  std::vector<Vec3> lo(nt), hi(nt);
  Vec3 box_lo = vertices_[tri_vertices_[0][0]], box_hi = box_lo;
  for (size_t t = 0; t < nt; ++t) {
    Tri& tri = tri_[t];
    for (int k = 0; k < 3; ++k) tri.v[k] = vertices_[tri_vertices_[t][k]];
    const Vec3 n = Cross(tri.v[1] - tri.v[0], tri.v[2] - tri.v[0]);
    tri.normal = n / Norm(n);
    lo[t] = hi[t] = tri.v[0];
    for (int k = 0; k < 3; ++k) {
      const Vec3 edge = tri.v[(k + 1) % 3] - tri.v[k];
      const Vec3 m = Cross(tri.normal, edge);
      tri.inward[k] = m / Norm(m);
      for (int a = 0; a < 3; ++a) {
        lo[t][a] = std::min(lo[t][a], tri.v[k][a]);
        hi[t][a] = std::max(hi[t][a], tri.v[k][a]);
      }
    }
    tri.bound_centre = 0.5 * (lo[t] + hi[t]);
    for (const Vec3& corner : tri.v) {
      tri.bound_radius = std::max(tri.bound_radius, Norm(corner - tri.bound_centre));
    }
    for (int a = 0; a < 3; ++a) {
      box_lo[a] = std::min(box_lo[a], lo[t][a]);
      box_hi[a] = std::max(box_hi[a], hi[t][a]);
    }
    if (!IsFinite(tri.normal) || !IsFinite(tri.inward[0]) || !IsFinite(tri.inward[1]) ||
        !IsFinite(tri.inward[2])) {
      return Fail(error, "triangle mesh: triangle " + std::to_string(t) +
                             " has no well-defined normal (degenerate)");
    }
  }
  length_scale_m_ = Norm(box_hi - box_lo) + std::max(Norm(box_lo), Norm(box_hi));
  BuildTopology();
  BuildPatches(options.flat_angle_rad);
  grid_.Build(lo, hi, options.grid_cell_m);
  return true;
}

void TriangleMesh::BuildTopology() {
  const auto nt = static_cast<int32_t>(tri_vertices_.size());
  // Every (triangle, local edge), sorted by its undirected vertex pair, groups shared edges.
  struct HalfEdge {
    int32_t a = 0, b = 0, tri = 0, local = 0;
  };
  std::vector<HalfEdge> half(3 * static_cast<size_t>(nt));
  for (int32_t t = 0; t < nt; ++t) {
    for (int32_t k = 0; k < 3; ++k) {
      const int32_t u = tri_vertices_[t][k], w = tri_vertices_[t][(k + 1) % 3];
      half[3 * t + k] = {std::min(u, w), std::max(u, w), t, k};
    }
  }
  std::sort(half.begin(), half.end(), [](const HalfEdge& x, const HalfEdge& y) {
    return std::tie(x.a, x.b, x.tri, x.local) < std::tie(y.a, y.b, y.tri, y.local);
  });
  tri_edges_.assign(nt, {-1, -1, -1});
  edge_vertices_.clear();
  edge_tri_start_.assign(1, 0);
  edge_tri_.clear();
  edge_tri_inward_.clear();
  for (size_t i = 0; i < half.size(); ++i) {
    if (i == 0 || half[i].a != half[i - 1].a || half[i].b != half[i - 1].b) {
      if (i > 0) edge_tri_start_.push_back(static_cast<int32_t>(edge_tri_.size()));
      edge_vertices_.push_back({half[i].a, half[i].b});
    }
    const auto e = static_cast<int32_t>(edge_vertices_.size() - 1);
    tri_edges_[half[i].tri][half[i].local] = e;
    edge_tri_.push_back(half[i].tri);
    edge_tri_inward_.push_back(tri_[half[i].tri].inward[half[i].local]);
  }
  edge_tri_start_.push_back(static_cast<int32_t>(edge_tri_.size()));

  // Edges at each vertex, with unit directions away from the vertex.
  const size_t nv = vertices_.size();
  vertex_edge_start_.assign(nv + 1, 0);
  for (const auto& ev : edge_vertices_) {
    ++vertex_edge_start_[ev[0] + 1];
    ++vertex_edge_start_[ev[1] + 1];
  }
  std::partial_sum(vertex_edge_start_.begin(), vertex_edge_start_.end(),
                   vertex_edge_start_.begin());
  vertex_edge_.assign(vertex_edge_start_.back(), -1);
  vertex_edge_dir_.assign(vertex_edge_start_.back(), Vec3{});
  std::vector<int32_t> fill(vertex_edge_start_.begin(), vertex_edge_start_.end() - 1);
  for (int32_t e = 0; e < static_cast<int32_t>(edge_vertices_.size()); ++e) {
    for (int side = 0; side < 2; ++side) {
      const int32_t v = edge_vertices_[e][side], w = edge_vertices_[e][1 - side];
      const Vec3 d = vertices_[w] - vertices_[v];
      vertex_edge_[fill[v]] = e;
      vertex_edge_dir_[fill[v]++] = d / Norm(d);
    }
  }
}

void TriangleMesh::BuildPatches(double flat_angle_rad) {
  // Flood fill across two-triangle edges where the surface continues (the triangles lie on
  // opposite sides of the edge, not folded back onto each other); a triangle joins a patch if its
  // normal is within flat_angle_rad of the patch's first triangle (either orientation: meshes
  // are two-sided).
  const double min_cos = std::cos(flat_angle_rad);
  auto continues = [&](int32_t e) {
    const int32_t k = edge_tri_start_[e];
    return edge_tri_start_[e + 1] - k == 2 && Dot(edge_tri_inward_[k], edge_tri_inward_[k + 1]) < 0;
  };
  const auto nt = static_cast<int32_t>(tri_vertices_.size());
  tri_patch_.assign(nt, -1);
  patch_count_ = 0;
  std::vector<int32_t> stack;
  for (int32_t seed = 0; seed < nt; ++seed) {
    if (tri_patch_[seed] >= 0) continue;
    const auto patch = static_cast<int32_t>(patch_count_++);
    const Vec3 n0 = tri_[seed].normal;
    tri_patch_[seed] = patch;
    stack.assign(1, seed);
    while (!stack.empty()) {
      const int32_t t = stack.back();
      stack.pop_back();
      for (int32_t e : tri_edges_[t]) {
        if (!continues(e)) continue;
        const std::span<const int32_t> tris = EdgeTriangles(e);
        const int32_t other = tris[0] == t ? tris[1] : tris[0];
        if (tri_patch_[other] >= 0 || std::abs(Dot(tri_[other].normal, n0)) < min_cos) continue;
        tri_patch_[other] = patch;
        stack.push_back(other);
      }
    }
  }
  edge_flat_.assign(edge_vertices_.size(), 0);
  for (size_t e = 0; e < edge_vertices_.size(); ++e) {
    const std::span<const int32_t> tris = EdgeTriangles(static_cast<int32_t>(e));
    edge_flat_[e] =
        continues(static_cast<int32_t>(e)) && tri_patch_[tris[0]] == tri_patch_[tris[1]];
  }
  vertex_flat_.assign(vertices_.size(), 0);
  for (size_t v = 0; v < vertices_.size(); ++v) {
    bool flat = vertex_edge_start_[v] < vertex_edge_start_[v + 1];
    for (int32_t k = vertex_edge_start_[v]; k < vertex_edge_start_[v + 1]; ++k) {
      flat = flat && edge_flat_[vertex_edge_[k]];
    }
    vertex_flat_[v] = flat;
  }
}

std::span<const int32_t> TriangleMesh::EdgeTriangles(int32_t e) const {
  return {edge_tri_.data() + edge_tri_start_[e],
          static_cast<size_t>(edge_tri_start_[e + 1] - edge_tri_start_[e])};
}

bool TriangleMesh::IsClosed() const {
  for (size_t e = 0; e < edge_vertices_.size(); ++e) {
    if (edge_tri_start_[e + 1] - edge_tri_start_[e] != 2) return false;
  }
  return true;
}

double TriangleMesh::SignedVolume() const {
  double six_volume = 0;
  for (const Tri& t : tri_) {
    six_volume += Dot(t.v[0] + offset_, Cross(t.v[1] + offset_, t.v[2] + offset_));
  }
  return six_volume / 6.0;
}

double TriangleMesh::Area() const {
  double twice = 0;
  for (const Tri& t : tri_) twice += Norm(Cross(t.v[1] - t.v[0], t.v[2] - t.v[0]));
  return twice / 2.0;
}

}  // namespace demcal::core
