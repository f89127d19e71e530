// TriangleMesh::SphereContacts: the closest point of each triangle within reach, then the
// contact rules described in triangle_mesh.h (normal cones, one report per shared feature,
// planar patches).
#include <algorithm>
#include <cmath>
#include <limits>

#include "core/walls/triangle_mesh.h"
#include "core/walls/wall_geometry.h"

namespace demcal::core {
namespace {

// Rounding allowance of the cone tests and of "the same point", in metres:
// kConeTolerance × radius + kRoundoff × (mesh size + coordinate magnitude).
constexpr double kConeTolerance = 1e-9;
constexpr double kRoundoff = 1e-12;

bool Contains(const std::array<int32_t, 3>& a, int32_t x) {
  return a[0] == x || a[1] == x || a[2] == x;
}

}  // namespace

bool TriangleMesh::EdgeConeHolds(int32_t edge, const Vec3& to_centre, double tolerance) const {
  // Moving from the edge into any of its triangles must not approach the centre.
  for (int32_t k = edge_tri_start_[edge]; k < edge_tri_start_[edge + 1]; ++k) {
    if (Dot(to_centre, edge_tri_inward_[k]) > tolerance) return false;
  }
  return true;
}

bool TriangleMesh::VertexConeHolds(int32_t vertex, const Vec3& to_centre, double tolerance) const {
  // Moving from the vertex along any of its edges must not approach the centre (then no
  // direction into its triangles does either: those are non-negative mixes of edge directions).
  for (int32_t k = vertex_edge_start_[vertex]; k < vertex_edge_start_[vertex + 1]; ++k) {
    if (Dot(to_centre, vertex_edge_dir_[k]) > tolerance) return false;
  }
  return true;
}

bool TriangleMesh::TriangleCandidate(int32_t t, const Vec3& c, double radius, double tolerance,
                                     MeshContact* m, bool* in_cone) const {
  const Tri& tri = tri_[t];
  const double reach = radius + tri.bound_radius;
  if (Norm2(c - tri.bound_centre) >= reach * reach) return false;
  const double height = Dot(c - tri.v[0], tri.normal);
  if (std::abs(height) >= radius) return false;
  const TriangleClosestPoint cp = ClosestPointOnTriangle(c, tri.v[0], tri.v[1], tri.v[2]);
  const Vec3 front = height >= 0 ? tri.normal : -tri.normal;
  m->triangle = t;
  *in_cone = true;
  if (cp.region == TriangleRegion::kFace) {
    // Exact plane distance, so that coplanar neighbours agree to rounding.
    *m = {front, radius - std::abs(height), c - height * tri.normal, MeshFeatureKind::kFace, t, t};
    return true;
  }
  const int local = RegionLocalIndex(cp.region);
  Vec3 point = cp.point_m;
  MeshFeatureKind kind = MeshFeatureKind::kVertex;
  int32_t feature = tri_vertices_[t][local];
  if (IsEdgeRegion(cp.region)) {
    kind = MeshFeatureKind::kEdge;
    feature = tri_edges_[t][local];
    // A foot within rounding of an end of the edge is that vertex (a feature shared by more
    // triangles, which must all name it the same way).
    for (int32_t v : edge_vertices_[feature]) {
      if (Norm2(point - vertices_[v]) <= tolerance * tolerance) {
        kind = MeshFeatureKind::kVertex;
        feature = v;
        point = vertices_[v];
        break;
      }
    }
  }
  const Vec3 d = c - point;
  const double distance = Norm(d);
  if (distance >= radius) return false;
  *m = {distance > 0 ? d / distance : front, radius - distance, point, kind, feature, t};
  *in_cone = kind == MeshFeatureKind::kEdge ? EdgeConeHolds(feature, d, tolerance)
                                            : VertexConeHolds(feature, d, tolerance);
  return true;
}

template <class ForEachCandidate>
void TriangleMesh::CollectContacts(const Vec3& c, double radius_m,
                                   ForEachCandidate&& for_each_candidate,
                                   std::vector<MeshContact>& out) const {
  const double tolerance = kConeTolerance * radius_m + kRoundoff * length_scale_m_;
  // The nearest candidate that failed its cone test: in exact arithmetic the nearest point of
  // the mesh always passes, so this only guards against losing a contact to rounding.
  MeshContact fallback;
  for_each_candidate([&](uint32_t item) {
    MeshContact m;
    bool in_cone = false;
    if (!TriangleCandidate(static_cast<int32_t>(item), c, radius_m, tolerance, &m, &in_cone)) {
      return;
    }
    if (in_cone) {
      out.push_back(m);
    } else if (m.overlap_m > fallback.overlap_m) {
      fallback = m;
    }
  });
  if (out.empty()) {
    if (fallback.triangle < 0) return;
    out.push_back(fallback);
  }
  ApplyContactRules(c, radius_m, out);
}

void TriangleMesh::SphereContacts(const Vec3& centre_m, double radius_m,
                                  std::vector<MeshContact>& out) const {
  out.clear();
  if (!IsFinite(centre_m) || !std::isfinite(radius_m) || !(radius_m > 0)) return;
  const Vec3 c = centre_m - offset_;
  const Vec3 reach{radius_m, radius_m, radius_m};
  CollectContacts(
      c, radius_m, [&](auto&& visit) { grid_.ForEachInBox(c - reach, c + reach, visit); }, out);
}

void TriangleMesh::SphereContacts(const Vec3& centre_m, double radius_m,
                                  std::span<const int32_t> near,
                                  std::vector<MeshContact>& out) const {
  out.clear();
  if (!IsFinite(centre_m) || !std::isfinite(radius_m) || !(radius_m > 0)) return;
  CollectContacts(
      centre_m - offset_, radius_m,
      [&](auto&& visit) {
        for (int32_t t : near) visit(static_cast<uint32_t>(t));
      },
      out);
}

void TriangleMesh::ApplyContactRules(const Vec3& c, double radius,
                                     std::vector<MeshContact>& out) const {
  // Priority face > edge > vertex: a feature already covered by a contact of a face (edge)
  // that contains it is not reported again; nor is a feature reported twice. A dropped entry is
  // marked with triangle = -1. Faces are never dropped here.
  auto face_contains = [&](auto&& has) {
    return std::any_of(out.begin(), out.end(), [&](const MeshContact& m) {
      return m.kind == MeshFeatureKind::kFace && has(m.triangle);
    });
  };
  auto kept_before = [&](size_t i, auto&& same) {
    return std::any_of(out.begin(), out.begin() + static_cast<std::ptrdiff_t>(i),
                       [&](const MeshContact& m) { return m.triangle >= 0 && same(m); });
  };
  for (size_t i = 0; i < out.size(); ++i) {
    MeshContact& m = out[i];
    if (m.kind != MeshFeatureKind::kEdge) continue;
    const int32_t e = m.feature;
    if (face_contains([&](int32_t t) { return Contains(tri_edges_[t], e); }) ||
        kept_before(i, [&](const MeshContact& k) {
          return k.kind == MeshFeatureKind::kEdge && k.feature == e;
        })) {
      m.triangle = -1;
    }
  }
  for (size_t i = 0; i < out.size(); ++i) {
    MeshContact& m = out[i];
    if (m.kind != MeshFeatureKind::kVertex) continue;
    const int32_t v = m.feature;
    const bool covered = face_contains([&](int32_t t) { return Contains(tri_vertices_[t], v); }) ||
                         kept_before(out.size(),
                                     [&](const MeshContact& k) {
                                       return k.kind == MeshFeatureKind::kEdge &&
                                              (edge_vertices_[k.feature][0] == v ||
                                               edge_vertices_[k.feature][1] == v);
                                     }) ||
                         kept_before(i, [&](const MeshContact& k) {
                           return k.kind == MeshFeatureKind::kVertex && k.feature == v;
                         });
    if (covered) m.triangle = -1;
  }
  std::erase_if(out, [](const MeshContact& m) { return m.triangle < 0; });

  // Faces are keyed by planar patch; an edge or vertex inside a patch is that patch's face,
  // with the plane's normal and distance.
  for (MeshContact& m : out) {
    const bool flat = (m.kind == MeshFeatureKind::kEdge && edge_flat_[m.feature]) ||
                      (m.kind == MeshFeatureKind::kVertex && vertex_flat_[m.feature]);
    if (flat) {
      const Tri& tri = tri_[m.triangle];
      const double height = Dot(c - tri.v[0], tri.normal);
      m.normal = height >= 0 ? tri.normal : -tri.normal;
      m.overlap_m = radius - std::abs(height);
      m.point_m = c - height * tri.normal;
      m.kind = MeshFeatureKind::kFace;
    }
    if (m.kind == MeshFeatureKind::kFace) m.feature = tri_patch_[m.triangle];
    m.point_m += offset_;
  }
  // One contact per key (e.g. coincident duplicate triangles of one patch): keep the deepest.
  for (size_t i = 0; i < out.size(); ++i) {
    if (out[i].triangle < 0) continue;
    for (size_t j = i + 1; j < out.size(); ++j) {
      if (out[j].triangle >= 0 && out[j].Key() == out[i].Key()) {
        if (out[j].overlap_m > out[i].overlap_m) std::swap(out[i], out[j]);
        out[j].triangle = -1;
      }
    }
  }
  std::erase_if(out, [](const MeshContact& m) { return m.triangle < 0; });
}

void TriangleMesh::CandidateTriangles(const Vec3& centre_m, double radius_m,
                                      std::vector<int32_t>& out) const {
  out.clear();
  if (!IsFinite(centre_m) || !std::isfinite(radius_m) || !(radius_m > 0)) return;
  const Vec3 c = centre_m - offset_;
  grid_.ForEachInBox(c - Vec3{radius_m, radius_m, radius_m}, c + Vec3{radius_m, radius_m, radius_m},
                     [&](uint32_t item) {
                       const Tri& tri = tri_[item];
                       for (int a = 0; a < 3; ++a) {
                         const double lo = std::min({tri.v[0][a], tri.v[1][a], tri.v[2][a]});
                         const double hi = std::max({tri.v[0][a], tri.v[1][a], tri.v[2][a]});
                         if (hi < c[a] - radius_m || lo > c[a] + radius_m) return;
                       }
                       out.push_back(static_cast<int32_t>(item));
                     });
  std::sort(out.begin(), out.end());
}

void TriangleMesh::NearTriangles(const Vec3& centre_m, double reach_m,
                                 std::vector<int32_t>& out) const {
  CandidateTriangles(centre_m, reach_m, out);
  const Vec3 c = centre_m - offset_;
  const double limit = reach_m + kConeTolerance * reach_m + kRoundoff * length_scale_m_;
  std::erase_if(out, [&](int32_t t) {
    const Tri& tri = tri_[t];
    const Vec3 closest = ClosestPointOnTriangle(c, tri.v[0], tri.v[1], tri.v[2]).point_m;
    return Norm2(c - closest) > limit * limit;
  });
}

}  // namespace demcal::core
