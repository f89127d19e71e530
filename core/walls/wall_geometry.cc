#include "core/walls/wall_geometry.h"

#include <algorithm>
#include <cmath>

namespace demcal::core {
namespace {

constexpr double kUnitTolerance = 1e-9;

bool Fail(std::string* error, const std::string& message) {
  if (error) *error = message;
  return false;
}

bool IsUnit(const Vec3& v) { return IsFinite(v) && std::abs(Norm(v) - 1.0) <= kUnitTolerance; }

// Axial height h of p, and the unit radial direction (arbitrary but fixed on the axis).
struct AxialFrame {
  double height = 0;
  double radius = 0;
  Vec3 radial;
};

AxialFrame ToAxial(const Vec3& axis_point, const Vec3& axis, const Vec3& p) {
  const AxialOffset a = ToAxialOffset(axis_point, axis, p);
  if (a.radius > 0) return {a.height, a.radius, a.radial / a.radius};
  return {a.height, 0.0, AnyPerpendicular(axis)};
}

// Lifts a meridian-plane vector (radial, axial components) back to 3D.
Vec3 Lift(const AxialFrame& f, const Vec3& axis, double radial, double axial) {
  return radial * f.radial + axial * axis;
}

}  // namespace

Vec3 AnyPerpendicular(const Vec3& axis) {
  const double ax = std::abs(axis.x), ay = std::abs(axis.y), az = std::abs(axis.z);
  const Vec3 helper = (ax <= ay && ax <= az) ? Vec3{1, 0, 0}
                      : (ay <= az)           ? Vec3{0, 1, 0}
                                             : Vec3{0, 0, 1};
  const Vec3 p = Cross(axis, helper);
  return p / Norm(p);
}

bool PlaneSurface::IsValid(std::string* error) const {
  if (!IsFinite(point_m)) return Fail(error, "plane: point_m is not finite");
  if (!IsUnit(normal)) return Fail(error, "plane: normal must be a unit vector");
  return true;
}

bool CylinderSurface::IsValid(std::string* error) const {
  if (!IsFinite(axis_point_m)) return Fail(error, "cylinder: axis_point_m is not finite");
  if (!IsUnit(axis)) return Fail(error, "cylinder: axis must be a unit vector");
  if (!(radius_m > 0) || !std::isfinite(radius_m)) {
    return Fail(error, "cylinder: radius_m must be finite and > 0");
  }
  if (!(axial_min_m < axial_max_m)) {
    return Fail(error, "cylinder: axial_min_m must be < axial_max_m");
  }
  return true;
}

bool ConeFrustumSurface::IsValid(std::string* error) const {
  if (!IsFinite(axis_point_m)) return Fail(error, "cone: axis_point_m is not finite");
  if (!IsUnit(axis)) return Fail(error, "cone: axis must be a unit vector");
  if (!std::isfinite(height0_m) || !std::isfinite(height1_m) || height0_m == height1_m) {
    return Fail(error, "cone: height0_m and height1_m must be finite and different");
  }
  if (!(radius0_m >= 0) || !(radius1_m >= 0) || !std::isfinite(radius0_m) ||
      !std::isfinite(radius1_m) || (radius0_m == 0 && radius1_m == 0)) {
    return Fail(error, "cone: radius0_m and radius1_m must be finite, >= 0 and not both 0");
  }
  return true;
}

WallProximity ClosestOnPlane(const PlaneSurface& plane, const Vec3& centre_m) {
  const double d = Dot(centre_m - plane.point_m, plane.normal);
  return {plane.normal, d, centre_m - d * plane.normal, false};
}

WallProximity ClosestOnCylinder(const CylinderSurface& cyl, const Vec3& centre_m) {
  const AxialFrame f = ToAxial(cyl.axis_point_m, cyl.axis, centre_m);
  const double side = cyl.inside ? -1.0 : 1.0;  // normal = side · radial on the open surface
  const double h = std::clamp(f.height, cyl.axial_min_m, cyl.axial_max_m);
  const Vec3 point = cyl.axis_point_m + h * cyl.axis + cyl.radius_m * f.radial;
  if (h == f.height) {
    return {side * f.radial, side * (f.radius - cyl.radius_m), point, false};
  }
  const Vec3 diff = centre_m - point;
  const double dist = Norm(diff);
  const Vec3 normal = dist > 0 ? diff / dist : side * f.radial;
  return {normal, dist, point, true};
}

WallProximity ClosestOnConeFrustum(const ConeFrustumSurface& cone, const Vec3& centre_m) {
  // Work in the meridian half-plane of the centre, coordinates (radial, axial): the surface is
  // the segment P0 = (r0, h0) → P1 = (r1, h1) with h0 < h1, and the nearest point of the surface
  // of revolution lies in that half-plane.
  const bool swap = cone.height0_m > cone.height1_m;
  const double r0 = swap ? cone.radius1_m : cone.radius0_m;
  const double h0 = swap ? cone.height1_m : cone.height0_m;
  const double r1 = swap ? cone.radius0_m : cone.radius1_m;
  const double h1 = swap ? cone.height0_m : cone.height1_m;
  const AxialFrame f = ToAxial(cone.axis_point_m, cone.axis, centre_m);

  const double len = std::hypot(r1 - r0, h1 - h0);
  const double tr = (r1 - r0) / len, th = (h1 - h0) / len;
  const double qr = f.radius - r0, qh = f.height - h0;
  const double s = qr * tr + qh * th;  // position of the projection along the segment
  // Normal of the segment towards the axis (the inside), since th > 0.
  const double side = cone.inside ? 1.0 : -1.0;
  const double nr = -th * side, nh = tr * side;
  if (s >= 0 && s <= len) {
    const double dist = qr * nr + qh * nh;
    const Vec3 point = cone.axis_point_m + Lift(f, cone.axis, r0 + s * tr, h0 + s * th);
    return {Lift(f, cone.axis, nr, nh), dist, point, false};
  }
  const double rim_r = s < 0 ? r0 : r1, rim_h = s < 0 ? h0 : h1;
  const double dr = f.radius - rim_r, dh = f.height - rim_h;
  const double dist = std::hypot(dr, dh);
  const Vec3 point = cone.axis_point_m + Lift(f, cone.axis, rim_r, rim_h);
  const Vec3 normal =
      dist > 0 ? Lift(f, cone.axis, dr / dist, dh / dist) : Lift(f, cone.axis, nr, nh);
  return {normal, dist, point, true};
}

TriangleClosestPoint ClosestPointOnTriangle(const Vec3& p, const Vec3& a, const Vec3& b,
                                            const Vec3& c) {
  // Test the Voronoi regions of the vertices, then of the edges; otherwise p projects inside.
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = Dot(ab, ap), d2 = Dot(ac, ap);
  if (d1 <= 0 && d2 <= 0) return {a, TriangleRegion::kVertex0};

  const Vec3 bp = p - b;
  const double d3 = Dot(ab, bp), d4 = Dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return {b, TriangleRegion::kVertex1};

  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) {
    return {a + (d1 / (d1 - d3)) * ab, TriangleRegion::kEdge0};
  }

  const Vec3 cp = p - c;
  const double d5 = Dot(ab, cp), d6 = Dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return {c, TriangleRegion::kVertex2};

  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) {
    return {a + (d2 / (d2 - d6)) * ac, TriangleRegion::kEdge2};
  }

  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
    return {b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b), TriangleRegion::kEdge1};
  }

  const double denom = 1.0 / (va + vb + vc);
  return {a + (vb * denom) * ab + (vc * denom) * ac, TriangleRegion::kFace};
}

}  // namespace demcal::core
