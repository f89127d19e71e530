#pragma once
// TriangleMesh: an indexed, welded triangle mesh for wall geometry (from an STL soup), with the
// sphere–mesh contact query a DEM wall needs. SphereContacts reports each touching feature of
// the surface once: a sphere rolling over the shared edge or vertex of coplanar triangles feels
// one continuous plane contact (no bump, no doubled force), while a convex edge or corner gives
// one edge or vertex contact and a concave corner gives one contact per face.
//
// How contacts are chosen. Each triangle within reach yields its closest point, on its face, an
// edge or a vertex. An edge (vertex) point is kept only if the direction u from it to the centre
// lies in the edge's (vertex's) normal cone, i.e. moving from the point into any triangle that
// shares the edge (along any edge at the vertex) does not get closer; otherwise that neighbour
// owns the contact. Shared features are reported once, a face contact beats an edge or vertex
// contact of the same triangle (and an edge beats its vertices) when rounding leaves both, and
// an edge or vertex inside a planar patch (all its triangles coplanar) is reported as the
// patch's face with the exact plane normal and distance. Meshes are two-sided.
//
// Feature keys. MeshContact::Key() is stable while the mesh exists (translation does not change
// it), so it can key per-contact history. Faces are keyed by planar patch (a maximal edge-
// connected set of coplanar triangles), so tangential history survives rolling across a plate.
//
// Units: metres. Thread-safety: const methods are safe to call concurrently; Translate is not.
// SphereContacts allocates nothing once `out` has grown to its working size.
//
// Usage:
//   std::string error;
//   auto mesh = TriangleMesh::FromSoup(ReadStl(path).triangles, {}, &error);
//   std::vector<MeshContact> contacts;
//   mesh->SphereContacts(centre, radius, contacts);   // overlap δ = radius − distance > 0
//   mesh->Translate(velocity * dt);                    // a moving wall
#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/walls/mesh_io.h"
#include "core/walls/triangle_grid.h"
#include "core/math/vec3.h"

namespace demcal::core {

enum class MeshFeatureKind : uint8_t { kFace, kEdge, kVertex };

struct MeshContact {
  Vec3 normal;           // unit, from the contact point towards the sphere centre
  double overlap_m = 0;  // radius − distance (> 0)
  Vec3 point_m;          // closest point on the mesh surface
  MeshFeatureKind kind = MeshFeatureKind::kFace;
  int32_t feature = -1;   // kFace: planar patch; kEdge: edge; kVertex: vertex index
  int32_t triangle = -1;  // a triangle that contains point_m

  // Stable per-feature key, e.g. for contact-history maps.
  uint64_t Key() const {
    return (static_cast<uint64_t>(kind) << 32) | static_cast<uint32_t>(feature);
  }
};

struct TriangleMeshOptions {
  // Corners closer than this are merged into one vertex. 0 = automatic: 1e-9 × the diagonal of
  // the bounding box (float32 STL coordinates of a shared corner are identical anyway). >= 0.
  double weld_tolerance_m = 0;
  // Cell size of the spatial grid; 0 = automatic (mean triangle size). Setting it near the
  // particle diameter is a good choice for meshes of large triangles. >= 0.
  double grid_cell_m = 0;
  // Neighbouring triangles whose normals differ by at most this angle are coplanar (one planar
  // patch). In [0, 0.1). Default 1e-6 rad.
  double flat_angle_rad = 1e-6;

  bool IsValid(std::string* error) const;
};

class TriangleMesh {
 public:
  // From a soup: welds corners, then as FromIndexed. Fails (nullopt, *error set) on invalid
  // options, non-finite coordinates, or no non-degenerate triangle.
  static std::optional<TriangleMesh> FromSoup(std::span<const StlTriangle> soup,
                                              const TriangleMeshOptions& options,
                                              std::string* error);
  // From vertices and corner indices (counter-clockwise seen from the front). Triangles that
  // repeat a vertex or have zero area (StlReadOptions tolerance) are dropped and counted, and so
  // are repeats of a triangle (the same three vertices, in either winding).
  static std::optional<TriangleMesh> FromIndexed(std::vector<Vec3> vertices,
                                                 std::span<const std::array<int32_t, 3>> triangles,
                                                 const TriangleMeshOptions& options,
                                                 std::string* error);

  // Clears `out` and fills it with the contacts of a sphere (see the file comment). A centre or
  // radius that is not finite, or radius <= 0, gives no contacts.
  void SphereContacts(const Vec3& centre_m, double radius_m, std::vector<MeshContact>& out) const;

  // The same, looking only at `near` (ascending triangle indices, as NearTriangles gives them):
  // the contacts of a sphere whose every triangle within radius_m is listed. A static wall keeps
  // each particle's near triangles from one neighbour rebuild to the next (WallContacts), so the
  // force pass tests two or three triangles instead of every one the grid cells hold.
  void SphereContacts(const Vec3& centre_m, double radius_m, std::span<const int32_t> near,
                      std::vector<MeshContact>& out) const;

  // Clears `out` and fills it with the triangles whose bounding boxes overlap the sphere's box,
  // in ascending order (the broad phase of SphereContacts).
  void CandidateTriangles(const Vec3& centre_m, double radius_m, std::vector<int32_t>& out) const;
  // Clears `out` and fills it with the triangles whose closest point lies within reach_m of the
  // centre (plus rounding), in ascending order.
  void NearTriangles(const Vec3& centre_m, double reach_m, std::vector<int32_t>& out) const;

  // Moves the whole mesh rigidly (O(1)); contacts and vertices are reported in the new place.
  void Translate(const Vec3& displacement_m) { offset_ += displacement_m; }
  Vec3 offset_m() const { return offset_; }

  size_t NumVertices() const { return vertices_.size(); }
  size_t NumTriangles() const { return tri_vertices_.size(); }
  size_t NumEdges() const { return edge_vertices_.size(); }
  size_t NumPatches() const { return patch_count_; }
  int64_t DroppedDegenerate() const { return dropped_degenerate_; }
  int64_t DroppedDuplicates() const { return dropped_duplicate_; }

  Vec3 Vertex(int32_t v) const { return vertices_[v] + offset_; }
  const std::array<int32_t, 3>& TriangleVertices(int32_t t) const { return tri_vertices_[t]; }
  const Vec3& TriangleNormal(int32_t t) const { return tri_[t].normal; }
  const std::array<int32_t, 2>& EdgeVertices(int32_t e) const { return edge_vertices_[e]; }
  std::span<const int32_t> EdgeTriangles(int32_t e) const;

  // Every edge is shared by exactly two triangles (a watertight surface).
  bool IsClosed() const;
  // Σ over triangles of v0 · (v1 × v2) / 6: the enclosed volume of a closed, outward-wound mesh.
  double SignedVolume() const;
  double Area() const;

 private:
  // Geometry per triangle, in mesh coordinates (without offset_).
  struct Tri {
    std::array<Vec3, 3> v;
    Vec3 normal;                 // unit, (v1 − v0) × (v2 − v0) normalised
    std::array<Vec3, 3> inward;  // unit, in-plane, ⟂ edge k, pointing into the triangle
    Vec3 bound_centre;           // a sphere holding the triangle (cheap rejection)
    double bound_radius = 0;
  };
  TriangleMesh() = default;
  bool Build(const TriangleMeshOptions& options, std::string* error);
  void BuildTopology();
  void BuildPatches(double flat_angle_rad);
  bool EdgeConeHolds(int32_t edge, const Vec3& to_centre, double tolerance) const;
  bool VertexConeHolds(int32_t vertex, const Vec3& to_centre, double tolerance) const;
  // Candidate → closest point with its feature; false if out of reach or outside its cone.
  bool TriangleCandidate(int32_t t, const Vec3& centre, double radius, double tolerance,
                         MeshContact* contact, bool* in_cone) const;
  // SphereContacts over the triangles for_each_candidate(visit) visits (mesh coordinates).
  template <class ForEachCandidate>
  void CollectContacts(const Vec3& c, double radius, ForEachCandidate&& for_each_candidate,
                       std::vector<MeshContact>& out) const;
  // Drops features already reported by a neighbour, then maps to patches and world coordinates.
  void ApplyContactRules(const Vec3& centre, double radius, std::vector<MeshContact>& out) const;

  std::vector<Vec3> vertices_;
  std::vector<std::array<int32_t, 3>> tri_vertices_;
  std::vector<std::array<int32_t, 3>> tri_edges_;  // edge k joins corners k and k+1
  std::vector<Tri> tri_;
  std::vector<int32_t> tri_patch_;
  size_t patch_count_ = 0;

  std::vector<std::array<int32_t, 2>> edge_vertices_;
  std::vector<int32_t> edge_tri_start_, edge_tri_;  // triangles of each edge (rows)
  std::vector<Vec3> edge_tri_inward_;               // inward normal of that triangle at the edge
  std::vector<uint8_t> edge_flat_;                  // inside a patch: two coplanar triangles

  std::vector<int32_t> vertex_edge_start_, vertex_edge_;  // edges at each vertex (rows)
  std::vector<Vec3> vertex_edge_dir_;                     // unit, from the vertex along the edge
  std::vector<uint8_t> vertex_flat_;                      // all its edges flat

  TriangleGrid grid_;
  Vec3 offset_;
  double length_scale_m_ = 1;  // bounding-box diagonal plus coordinate magnitude (tolerances)
  int64_t dropped_degenerate_ = 0;
  int64_t dropped_duplicate_ = 0;
};

}  // namespace demcal::core
