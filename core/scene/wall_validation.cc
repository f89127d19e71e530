#include "core/scene/wall_validation.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "core/limits/physical_limits.h"
#include "core/scene/scene.h"
#include "core/walls/triangle_mesh.h"
#include "core/walls/wall_extent.h"

namespace demcal::core {

void CheckSceneWall(const Scene& s, size_t i, FieldChecker& c) {
  const Wall& w = s.walls[i];
  const std::string f = IndexedField("walls", i);
  if (w.material < 0 || w.material >= static_cast<int>(s.materials.size()))
    c.Fail("field '" + f + ".material' names no defined material");
  std::string message;
  const bool shape_ok = std::visit(
      [&](const auto& shape) {
        using S = std::decay_t<decltype(shape)>;
        if constexpr (std::is_same_v<S, MeshRef>) {
          if (shape.mesh && IsFinite(shape.offset_m)) return true;
          message = shape.mesh ? "mesh: offset_m is not finite"
                               : "mesh: mesh holds no triangle mesh (read the STL file with "
                                 "ReadMeshWall before validating the scene)";
          return false;
        } else {
          return shape.IsValid(&message);
        }
      },
      w.shape);
  if (!shape_ok) {
    const size_t colon = message.find(": ");
    const size_t space = message.find(' ', colon + 2);
    if (colon == std::string::npos || space == std::string::npos) {
      c.Fail("field '" + f + "' (" + ShapeName(w.shape) + "): " + message);
    } else {
      c.Fail("field '" + f + "." + message.substr(colon + 2, space - colon - 2) + "'" +
             message.substr(space) + " (" + ShapeName(w.shape) + " '" + w.name + "')");
    }
  }
  // Finite is not enough for the round walls' sizes either (limits::kWallRadius, kCoordinate);
  // an unbounded cylinder keeps its infinite axial ends.
  if (const auto* cyl = std::get_if<CylinderSurface>(&w.shape); cyl && c.ok()) {
    c.Within(f + ".radius_m", cyl->radius_m, limits::kWallRadius, "m");
    if (std::isfinite(cyl->axial_min_m))
      c.Within(f + ".axial_min_m", cyl->axial_min_m, limits::kCoordinate, "m");
    if (std::isfinite(cyl->axial_max_m))
      c.Within(f + ".axial_max_m", cyl->axial_max_m, limits::kCoordinate, "m");
  }
  if (const auto* cone = std::get_if<ConeFrustumSurface>(&w.shape); cone && c.ok()) {
    c.Within(f + ".radius0_m", cone->radius0_m, limits::kWallRadius, "m");
    c.Within(f + ".radius1_m", cone->radius1_m, limits::kWallRadius, "m");
    c.Within(f + ".height0_m", cone->height0_m, limits::kCoordinate, "m");
    c.Within(f + ".height1_m", cone->height1_m, limits::kCoordinate, "m");
  }
  if (!c.ok()) return;
  const char* axes = "xyz";
  // docs/scene_format.md: no wall across a periodic axis (particles would wrap through it); a
  // wall a particle radius inside the periodic box, or unchanged along the axis, is fine.
  // (A periodic axis along gravity is reported below, as the more basic mistake.)
  for (int a = 0; a < 3 && c.ok(); ++a) {
    if (!s.periodic[a] || s.gravity_m_s2[a] != 0 || InvariantAlongAxis(w, a)) continue;
    const AxisInterval x = WallExtent(w, a, s.time.duration_s);
    const double margin = 0.5 * s.MaxDiameter();
    if (x.lo_m >= s.domain_min_m[a] + margin && x.hi_m <= s.domain_max_m[a] - margin) continue;
    std::ostringstream os;
    os << "field '" << f << "' (" << ShapeName(w.shape) << " '" << w.name
       << "') crosses the periodic axis " << axes[a] << ": it ";
    if (std::isinf(x.lo_m) || std::isinf(x.hi_m))
      os << "is unbounded along " << axes[a];
    else
      os << "reaches [" << x.lo_m << ", " << x.hi_m << "] m along " << axes[a];
    os << ", the periodic domain is [" << s.domain_min_m[a]
       << ", " << s.domain_max_m[a] << "] m and a wall must stay a particle radius (" << margin
       << " m) inside it or be unchanged along the axis (a plane parallel to it, an infinite "
       << "cylinder along it); drop the wall (a box: its " << axes[a] << " faces) or periodic."
       << axes[a];
    c.Fail(os.str());
  }
  if (const auto* ref = std::get_if<MeshRef>(&w.shape);
      ref && ref->mesh && ref->mesh->NumVertices() > 0 && c.ok()) {
    // A mesh that never meets the domain is a unit or offset mistake (mm read as m).
    Vec3 lo = ref->mesh->Vertex(0) + ref->offset_m, hi = lo;
    for (size_t v = 0; v < ref->mesh->NumVertices(); ++v)
      for (int a = 0; a < 3; ++a) {
        const double x = ref->mesh->Vertex(static_cast<int32_t>(v))[a] + ref->offset_m[a];
        lo[a] = std::min(lo[a], x);
        hi[a] = std::max(hi[a], x);
      }
    const double travel =
        Norm(w.velocity_m_s) *
        (std::isinf(w.motion_end_s) ? s.time.duration_s : w.motion_end_s - w.motion_start_s);
    for (int a = 0; a < 3; ++a)
      if (hi[a] + travel < s.domain_min_m[a] || lo[a] - travel > s.domain_max_m[a]) {
        std::ostringstream os;
        os << "field '" << f << "' (mesh '" << w.name << "' from " << ref->source
           << ") lies entirely outside the domain along " << axes[a] << ": the mesh spans ["
           << lo[a] << ", " << hi[a] << "] m, the domain [" << s.domain_min_m[a] << ", "
           << s.domain_max_m[a] << "] m; check the STL's units (scale) and offset_m";
        c.Fail(os.str());
        break;
      }
  }
  c.Magnitude(f + ".velocity_m_s", w.velocity_m_s, limits::kSpeed, "m/s");
  const char* origin = std::holds_alternative<MeshRef>(w.shape)        ? ".offset_m"
                       : std::holds_alternative<PlaneSurface>(w.shape) ? ".point_m"
                                                                       : ".axis_point_m";
  c.Point(f + origin, ShapeOrigin(w.shape));
  c.Point(f + ".load_point_m", w.load_point_m);
  c.Range(f + ".motion_start_s", w.motion_start_s, 0, 1e9, false, false, "s");
  if (!std::isinf(w.motion_end_s) || w.motion_end_s < 0)
    c.Range(f + ".motion_end_s", w.motion_end_s, w.motion_start_s, 1e9, false, false, "s");
}

}  // namespace demcal::core
