#include "core/walls/walls.h"

#include <algorithm>

namespace demcal::core {

Wall::Wall(const PlaneWall& plane)
    : name(plane.name),
      material(plane.material),
      shape(PlaneSurface{plane.point_m, plane.normal}),
      velocity_m_s(plane.velocity_m_s) {}

bool Wall::Moves() const {
  return !(velocity_m_s == Vec3{}) && motion_end_s > motion_start_s;
}

Vec3 Wall::DisplacementAt(double time_s) const {
  if (!Moves()) return {};
  return velocity_m_s * (std::clamp(time_s, motion_start_s, motion_end_s) - motion_start_s);
}

Vec3 Wall::VelocityAt(double time_s) const {
  return time_s >= motion_start_s && time_s < motion_end_s ? velocity_m_s : Vec3{};
}

const Vec3& ShapeOrigin(const WallShape& shape) {
  return std::visit(
      [](const auto& s) -> const Vec3& {
        using S = std::decay_t<decltype(s)>;
        if constexpr (std::is_same_v<S, PlaneSurface>) return s.point_m;
        else if constexpr (std::is_same_v<S, MeshRef>) return s.offset_m;
        else return s.axis_point_m;
      },
      shape);
}

Vec3& ShapeOrigin(WallShape& shape) {
  return const_cast<Vec3&>(ShapeOrigin(static_cast<const WallShape&>(shape)));
}

const char* ShapeName(const WallShape& shape) {
  static constexpr const char* kNames[] = {"plane", "cylinder", "cone", "mesh"};
  static_assert(std::variant_size_v<WallShape> == 4);
  return kNames[shape.index()];
}

BoxFaces BoxInnerFaces(const std::string& name, const Vec3& lo, const Vec3& hi, int material,
                       bool open_top) {
  BoxFaces box{{
      {name + ".xmin", lo, {1, 0, 0}, material, {}}, {name + ".xmax", hi, {-1, 0, 0}, material, {}},
      {name + ".ymin", lo, {0, 1, 0}, material, {}}, {name + ".ymax", hi, {0, -1, 0}, material, {}},
      {name + ".zmin", lo, {0, 0, 1}, material, {}},
  }};
  if (!open_top) box.faces.push_back({name + ".zmax", hi, {0, 0, -1}, material, {}});
  return box;
}

bool ReadMeshWall(const std::string& path, const MeshWallOptions& options, Wall* wall,
                  std::string* error) {
  std::string message;
  if (!options.mesh.IsValid(&message)) {
    if (error) *error = path + ": invalid mesh options: " + message;
    return false;
  }
  const StlReadResult stl = ReadStl(path, options.stl);
  if (!stl.ok()) {
    if (error) *error = stl.message;  // starts with the file name
    return false;
  }
  std::optional<TriangleMesh> mesh = TriangleMesh::FromSoup(stl.triangles, options.mesh, &message);
  if (!mesh) {
    if (error) *error = path + ": " + message;
    return false;
  }
  wall->shape = MeshRef{std::make_shared<const TriangleMesh>(std::move(*mesh)), {}, path};
  return true;
}

}  // namespace demcal::core
