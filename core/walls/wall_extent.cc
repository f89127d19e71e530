#include "core/walls/wall_extent.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace demcal::core {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kAlong = 1e-12;  // a unit vector component this small counts as zero

// A disk of radius r centred at c, perpendicular to the unit vector u: its range along axis a.
AxisInterval Disk(const Vec3& c, const Vec3& u, double r, int a) {
  const double half = r * std::sqrt(std::max(0.0, 1 - u[a] * u[a]));
  return {c[a] - half, c[a] + half};
}

AxisInterval Union(AxisInterval x, AxisInterval y) {
  return {std::min(x.lo_m, y.lo_m), std::max(x.hi_m, y.hi_m)};
}

// Between heights h0 and h1 on the axis (either may be infinite), radii r0, r1 there.
AxisInterval Frustum(const Vec3& point, const Vec3& u, double h0, double r0, double h1,
                     double r1, int a) {
  if (std::isinf(h0) || std::isinf(h1)) {
    if (std::abs(u[a]) > kAlong) return {-kInf, kInf};
    return Disk(point, u, std::max(r0, r1), a);
  }
  return Union(Disk(point + h0 * u, u, r0, a), Disk(point + h1 * u, u, r1, a));
}

}  // namespace

AxisInterval WallExtent(const Wall& wall, int a, double duration_s) {
  AxisInterval at_rest{-kInf, kInf};
  if (const auto* plane = std::get_if<PlaneSurface>(&wall.shape)) {
    if (std::abs(plane->normal[a]) > 1 - kAlong) at_rest = {plane->point_m[a], plane->point_m[a]};
  } else if (const auto* c = std::get_if<CylinderSurface>(&wall.shape)) {
    at_rest = Frustum(c->axis_point_m, c->axis, c->axial_min_m, c->radius_m, c->axial_max_m,
                      c->radius_m, a);
  } else if (const auto* k = std::get_if<ConeFrustumSurface>(&wall.shape)) {
    at_rest = Frustum(k->axis_point_m, k->axis, k->height0_m, k->radius0_m, k->height1_m,
                      k->radius1_m, a);
  } else if (const MeshRef& m = std::get<MeshRef>(wall.shape); m.mesh && m.mesh->NumVertices()) {
    at_rest = {kInf, -kInf};
    for (size_t v = 0; v < m.mesh->NumVertices(); ++v) {
      const double x = m.mesh->Vertex(static_cast<int32_t>(v))[a] + m.offset_m[a];
      at_rest = {std::min(at_rest.lo_m, x), std::max(at_rest.hi_m, x)};
    }
  }
  const double span = std::isinf(wall.motion_end_s) ? duration_s : wall.motion_end_s - wall.motion_start_s;
  const double travel = std::abs(wall.velocity_m_s[a]) * std::max(0.0, span);
  return {at_rest.lo_m - travel, at_rest.hi_m + travel};
}

bool InvariantAlongAxis(const Wall& wall, int a) {
  if (const auto* plane = std::get_if<PlaneSurface>(&wall.shape))
    return std::abs(plane->normal[a]) <= kAlong;
  if (const auto* c = std::get_if<CylinderSurface>(&wall.shape))
    return std::isinf(c->axial_min_m) && std::isinf(c->axial_max_m) &&
           std::abs(c->axis[a]) >= 1 - kAlong;
  return false;
}

}  // namespace demcal::core
