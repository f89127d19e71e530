#pragma once
// Closest points on wall primitives: an infinite plane, a (finite or infinite) cylinder, a cone
// frustum (a funnel) and a single triangle. These are the pure geometry a sphere–wall contact
// needs: given the sphere centre, the nearest surface point, the unit normal from that point
// towards the centre and the distance, so that overlap δ = R − distance_m (contact when δ > 0).
//
// Sides. A plane, a cylinder and a cone are one-sided: the sphere lives on one side (`normal` of
// the plane; inside or outside of the cylinder/cone) and distance_m is signed, negative once the
// centre has crossed the surface, so a sphere that tunnelled through is still pushed back. The
// rims of a finite cylinder or cone (the circles at its two ends) are edges: there the distance is
// unsigned and the normal points from the rim to the centre (on_edge = true). The ends are open:
// a funnel's orifice and its top are holes, not lids.
//
// Units: SI (metres). Axial positions ("heights") are measured along `axis` from `axis_point_m`.
// Thread-safety: free functions on values; no shared state.
//
// Usage:
//   ConeFrustumSurface funnel{.axis_point_m = {0, 0, 0}, .axis = {0, 0, 1},
//                             .height0_m = 0.0, .radius0_m = 0.01,    // orifice
//                             .height1_m = 0.1, .radius1_m = 0.05};   // top
//   const WallProximity w = ClosestOnConeFrustum(funnel, centre);
//   if (radius - w.distance_m > 0) { /* contact along w.normal */ }
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

#include "core/math/vec3.h"

namespace demcal::core {

// Where a wall surface is nearest to a sphere centre.
struct WallProximity {
  Vec3 normal;            // unit, from the surface towards the centre's side (see "Sides")
  double distance_m = 0;  // signed on the open surface, unsigned (>= 0) on a rim
  Vec3 point_m;           // the closest surface point
  bool on_edge = false;   // the closest point lies on a rim of a finite cylinder or cone
};

// An infinite plane; the sphere lives on the side `normal` points to.
struct PlaneSurface {
  Vec3 point_m;          // any point on the plane
  Vec3 normal{0, 0, 1};  // unit
  bool IsValid(std::string* error) const;
};

// A circular cylinder, infinite unless an axial range is given. Heights are along `axis` from
// `axis_point_m`; the surface spans [axial_min_m, axial_max_m] (either may be infinite).
struct CylinderSurface {
  Vec3 axis_point_m;
  Vec3 axis{0, 0, 1};   // unit
  double radius_m = 0;  // > 0
  double axial_min_m = -std::numeric_limits<double>::infinity();
  double axial_max_m = std::numeric_limits<double>::infinity();
  bool inside = true;  // true: the sphere lives inside (a silo); false: outside (a post)
  bool IsValid(std::string* error) const;
};

// The lateral surface of a cone frustum between two heights, e.g. a funnel: radius0_m at
// height0_m (the orifice, small end) and radius1_m at height1_m (the top). Either end may be the
// small one; a radius may be 0 (a full cone with its apex). Both ends are open.
struct ConeFrustumSurface {
  Vec3 axis_point_m;
  Vec3 axis{0, 0, 1};  // unit
  double height0_m = 0;
  double radius0_m = 0;  // >= 0
  double height1_m = 0;  // != height0_m
  double radius1_m = 0;  // >= 0, not both radii 0
  bool inside = true;    // true: the sphere lives inside (a funnel)
  bool IsValid(std::string* error) const;
};

WallProximity ClosestOnPlane(const PlaneSurface& plane, const Vec3& centre_m);
WallProximity ClosestOnCylinder(const CylinderSurface& cylinder, const Vec3& centre_m);
// Height of p along `axis` from `axis_point`, and its offset from the axis (unnormalised): the
// axial coordinates every surface of revolution starts from (wall_geometry.cc's ToAxial).
struct AxialOffset {
  double height = 0;
  double radius = 0;
  Vec3 radial;  // p's offset from the axis, of length `radius`
};
inline AxialOffset ToAxialOffset(const Vec3& axis_point, const Vec3& axis, const Vec3& p) {
  const Vec3 d = p - axis_point;
  const double h = Dot(d, axis);
  const Vec3 radial = d - h * axis;
  return {h, Norm(radial), radial};
}

// ClosestOnCylinder's distance_m (made unsigned for a shell, as ShellSide does) when the centre
// lies within the axial range; false beyond it, where the nearest point is on a rim. The same
// axial coordinates without the normal's division: the contact sweep and the wall rebuild ask it
// first, since most of a silo's grains near the wall are not touching it.
inline bool CylinderSideDistance(const CylinderSurface& cyl, bool shell, const Vec3& centre_m,
                                 double& distance_m) {
  const AxialOffset a = ToAxialOffset(cyl.axis_point_m, cyl.axis, centre_m);
  if (!(a.height >= cyl.axial_min_m && a.height <= cyl.axial_max_m)) return false;
  const double side = cyl.inside ? -1.0 : 1.0;
  const double distance = side * (a.radius - cyl.radius_m);
  distance_m = shell ? std::abs(distance) : distance;
  return true;
}
WallProximity ClosestOnConeFrustum(const ConeFrustumSurface& cone, const Vec3& centre_m);

// Which feature of triangle (v0, v1, v2) holds the closest point. Edge k joins v_k and v_{k+1}
// (edge 2 joins v2 and v0).
enum class TriangleRegion : uint8_t { kFace, kEdge0, kEdge1, kEdge2, kVertex0, kVertex1, kVertex2 };
inline bool IsEdgeRegion(TriangleRegion r) {
  return r == TriangleRegion::kEdge0 || r == TriangleRegion::kEdge1 || r == TriangleRegion::kEdge2;
}
// Local index (0..2) of the edge or vertex named by an edge/vertex region.
inline int RegionLocalIndex(TriangleRegion r) {
  return IsEdgeRegion(r) ? static_cast<int>(r) - 1 : static_cast<int>(r) - 4;
}

struct TriangleClosestPoint {
  Vec3 point_m;
  TriangleRegion region = TriangleRegion::kFace;
};

// Closest point of the (solid) triangle to p, by Voronoi regions of its features (Ericson, Real-
// Time Collision Detection, §5.1.5). Two-sided. The triangle must not be degenerate.
TriangleClosestPoint ClosestPointOnTriangle(const Vec3& p, const Vec3& v0, const Vec3& v1,
                                            const Vec3& v2);

// A unit vector perpendicular to the unit vector `axis` (deterministic).
Vec3 AnyPerpendicular(const Vec3& axis);

}  // namespace demcal::core
