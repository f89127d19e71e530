#pragma once
// Walls: the fixed or translating boundaries particles touch. A Wall has a name, a material (for
// the interaction table), a shape and an optional prescribed translation:
//   * PlaneSurface: an infinite plane; particles live on the side its normal points to.
//   * CylinderSurface: a circular cylinder, particles inside (a silo) or outside (a post), finite
//     (open ends with rims) or infinite.
//   * ConeFrustumSurface: a funnel's lateral surface with open ends (the orifice is a hole).
//   * MeshRef: a welded triangle mesh (e.g. from an STL file); a sphere may touch several of its
//     faces, edges and vertices at once, each a separate contact with its own history.
// Geometry and contact rules are in wall_geometry.h and triangle_mesh.h.
//
// Sides. A plane is one-sided: particles live where its normal points, and a centre that
// crossed it is pushed back. A mesh is two-sided. Cylinders and cones are thin shells by default
// (`shell`): a sphere on either side of the lateral surface is repelled from it, so particles that
// leave through an open end and pile up outside (the heap around a lifted cylinder, under a
// funnel) cannot be pulled through it. With shell = false they are one-sided like a plane, on the
// side their `inside` flag names (a silo or a post that particles must never cross).
//
// Motion: a wall with a non-zero velocity_m_s translates rigidly with it while
// motion_start_s <= t < motion_end_s, and stands still before and after: its displacement at
// time t is velocity_m_s · (clamp(t, start, end) − start). The contact sees the wall's velocity
// (relative sliding, damping). A lifted cylinder, a gate moving away, a pushing piston.
//
// Loads: the engine reports per wall the force the particles exert on it (N) and the torque
// about load_point_m (N·m), which moves with the wall (see Simulation::WallLoads).
//
// Ownership: a mesh is shared read-only (std::shared_ptr<const TriangleMesh>) between copies of
// a Scene, e.g. many simulations of one calibration; nothing modifies it after reading.
// Thread-safety: plain values; const use is safe from any thread.
//
// Usage:
//   scene.walls = BoxInnerFaces("box", {0, 0, 0}, {0.1, 0.1, 0.2}, steel, /*open_top=*/true);
//   Wall silo{"silo", steel, CylinderSurface{.axis_point_m = {0.05, 0.05, 0}, .radius_m = 0.04}};
//   silo.velocity_m_s = {0, 0, 0.01};  // lifted at 10 mm/s
//   scene.walls.push_back(silo);
//   MeshWallOptions millimetres;
//   millimetres.stl.scale = 0.001;
//   Wall hopper("hopper", steel, MeshRef{});
//   if (!ReadMeshWall("hopper.stl", millimetres, &hopper, &error)) ...;  // error names the file
//   scene.walls.push_back(hopper);
#include <limits>
#include <memory>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "core/walls/mesh_io.h"
#include "core/walls/triangle_mesh.h"
#include "core/math/vec3.h"
#include "core/walls/wall_geometry.h"

namespace demcal::core {

// A triangle-mesh wall: the mesh in its own coordinates, placed at offset_m (a translation).
struct MeshRef {
  std::shared_ptr<const TriangleMesh> mesh;
  Vec3 offset_m;       // the mesh's vertices are at vertex + offset_m
  std::string source;  // where it came from (file name), for messages
};

using WallShape = std::variant<PlaneSurface, CylinderSurface, ConeFrustumSurface, MeshRef>;

// The classic plane wall of DEM core I; converts implicitly to a Wall with a PlaneSurface.
struct PlaneWall {
  std::string name;
  Vec3 point_m;         // any point on the plane
  Vec3 normal;          // unit normal pointing into the region where particles live
  int material = 0;
  Vec3 velocity_m_s;    // prescribed translation (zero = fixed)
};

struct Wall {
  std::string name;
  int material = 0;
  WallShape shape;
  Vec3 velocity_m_s;  // prescribed translation velocity (zero = fixed)
  double motion_start_s = 0;
  double motion_end_s = std::numeric_limits<double>::infinity();
  Vec3 load_point_m;  // reference point of the reported torque; moves with the wall
  bool shell = true;  // cylinder and cone: two-sided thin shell (see "Sides"); else ignored
  // Taken away at this time (an orifice opened by removing its plug): from the first step that
  // ends at or after it, no particle touches the wall and its load is zero. Infinity: never.
  double remove_at_s = std::numeric_limits<double>::infinity();
  // Set by the engine on its placed copy (Simulation::walls()) once removed; not a scene input.
  bool removed = false;

  Wall() = default;
  Wall(std::string wall_name, int wall_material, WallShape wall_shape)
      : name(std::move(wall_name)), material(wall_material), shape(std::move(wall_shape)) {}
  Wall(const PlaneWall& plane);  // NOLINT(google-explicit-constructor): DEM core I scenes

  // The wall has a prescribed motion (it is a contact candidate of every particle).
  bool Moves() const;
  // Translation since t = 0 at time t, and the velocity at time t (see the file comment).
  Vec3 DisplacementAt(double time_s) const;
  Vec3 VelocityAt(double time_s) const;
};

// The translation origin of a shape: plane point, cylinder or cone axis point, mesh offset.
const Vec3& ShapeOrigin(const WallShape& shape);
Vec3& ShapeOrigin(WallShape& shape);
// "plane", "cylinder", "cone", "mesh".
const char* ShapeName(const WallShape& shape);

// What the particles exert on one wall during a step.
struct WallLoad {
  Vec3 force_N;     // total force on the wall
  Vec3 torque_N_m;  // total torque on the wall about point_m
  Vec3 point_m;     // the wall's load_point_m at that step (translated with the wall)
};

// The inner faces of an axis-aligned box (a closed container), named name.xmin ... name.zmax,
// as plane walls; assign to Scene::walls or iterate as PlaneWall.
struct BoxFaces {
  std::vector<PlaneWall> faces;
  auto begin() const { return faces.begin(); }
  auto end() const { return faces.end(); }
  size_t size() const { return faces.size(); }
  const PlaneWall& operator[](size_t i) const { return faces[i]; }
  operator std::vector<Wall>() const { return {faces.begin(), faces.end()}; }  // NOLINT
};
BoxFaces BoxInnerFaces(const std::string& name, const Vec3& min_m, const Vec3& max_m, int material,
                       bool open_top);

struct MeshWallOptions {
  StlReadOptions stl;        // scale (file units → metres), degenerate tolerance
  TriangleMeshOptions mesh;  // welding, grid cell (try about the particle diameter), flatness
};

// Reads an STL file into wall->shape (a MeshRef with offset 0, source = path) and leaves the
// other fields of *wall alone. False with a message naming the file on any read or mesh error.
bool ReadMeshWall(const std::string& path, const MeshWallOptions& options, Wall* wall,
                  std::string* error);

}  // namespace demcal::core
