// Wall descriptions (DEM core II, geometry): prescribed motion, box faces, scene validation of
// every wall kind with field names, reading STL files into mesh walls.
#include <catch2/catch.hpp>
#include <filesystem>
#include <limits>

#include "core/scene/scene.h"
#include "core/walls/wall_test_support.h"

using namespace demcal::core;
using namespace demcal::core::wall_test;

namespace {

std::string ValidationError(const Wall& wall) {
  Scene s = OneMaterialScene(0.002);
  s.domain_max_m = {1, 1, 1};
  s.walls = {PlaneWall{"floor", {}, {0, 0, 1}, 0, {}}, wall};
  std::string error;
  return s.IsValid(&error) ? std::string("valid") : error;
}

}  // namespace

TEST_CASE("a wall translates between motion_start_s and motion_end_s", "[unit]") {
  Wall w = PlaneWall{"gate", {1, 2, 3}, {0, 0, 1}, 0, {0.5, 0, 0}};
  CHECK(w.Moves());
  CHECK(w.DisplacementAt(2) == Vec3{1, 0, 0});
  w.motion_start_s = 1;
  w.motion_end_s = 3;
  CHECK(w.DisplacementAt(0.5) == Vec3{});
  CHECK(w.VelocityAt(0.5) == Vec3{});
  CHECK(w.DisplacementAt(2) == Vec3{0.5, 0, 0});
  CHECK(w.VelocityAt(2) == Vec3{0.5, 0, 0});
  CHECK(w.DisplacementAt(10) == Vec3{1, 0, 0});
  CHECK(w.VelocityAt(10) == Vec3{});
  CHECK(ShapeOrigin(w.shape) == Vec3{1, 2, 3});
  w.velocity_m_s = {};
  CHECK(!w.Moves());
}

TEST_CASE("box faces convert to plane walls", "[unit]") {
  const BoxFaces box = BoxInnerFaces("bin", {0, 0, 0}, {1, 2, 3}, 1, /*open_top=*/true);
  REQUIRE(box.size() == 5);
  CHECK(box[4].name == "bin.zmin");
  const std::vector<Wall> walls = box;
  REQUIRE(walls.size() == 5);
  const PlaneSurface& xmax = std::get<PlaneSurface>(walls[1].shape);
  CHECK(xmax.normal == Vec3{-1, 0, 0});
  CHECK(xmax.point_m == Vec3{1, 2, 3});
  CHECK(walls[1].material == 1);
  CHECK(!walls[1].Moves());
}

TEST_CASE("invalid walls are refused with the field named", "[unit]") {
  CHECK(ValidationError(PlaneWall{"floor", {}, {0, 0, 1}, 0, {}}) == "valid");
  CHECK_THAT(ValidationError(PlaneWall{"tilted", {}, {0, 0, 2}, 0, {}}),
             Catch::Contains("field 'walls[1].normal' must be a unit vector (plane 'tilted')"));
  Wall silo("silo", 0, CylinderSurface{.radius_m = 0});
  CHECK_THAT(ValidationError(silo),
             Catch::Contains("field 'walls[1].radius_m' must be finite and > 0 (cylinder 'silo')"));
  silo.shape = CylinderSurface{.radius_m = 0.1, .axial_min_m = 1, .axial_max_m = 0};
  CHECK_THAT(ValidationError(silo),
             Catch::Contains("field 'walls[1].axial_min_m' must be < axial_max_m"));
  const Wall flat_cone("hopper", 0, ConeFrustumSurface{.height0_m = 0, .radius0_m = 0.01,
                                                       .height1_m = 0, .radius1_m = 0.1});
  CHECK_THAT(ValidationError(flat_cone),
             Catch::Contains("field 'walls[1].height0_m' and height1_m must be finite and "
                             "different (cone 'hopper')"));
  CHECK_THAT(ValidationError(Wall("liner", 0, MeshRef{})),
             Catch::Contains("field 'walls[1].mesh' holds no triangle mesh"));
  Wall gate = PlaneWall{"gate", {}, {0, 0, 1}, 0, {1, 0, 0}};
  gate.motion_start_s = 2;
  gate.motion_end_s = 1;
  CHECK_THAT(ValidationError(gate), Catch::Contains("field 'walls[1].motion_end_s' = 1 s"));
  gate.motion_end_s = std::numeric_limits<double>::infinity();
  CHECK(ValidationError(gate) == "valid");
  gate.velocity_m_s.x = std::numeric_limits<double>::quiet_NaN();
  CHECK_THAT(ValidationError(gate), Catch::Contains("field 'walls[1].velocity_m_s'"));
  Wall steel = PlaneWall{"floor", {}, {0, 0, 1}, 3, {}};
  CHECK_THAT(ValidationError(steel),
             Catch::Contains("field 'walls[1].material' names no defined material"));
}

TEST_CASE("an STL file is read into a mesh wall, a bad one is reported by name", "[unit]") {
  const std::string path =
      (std::filesystem::temp_directory_path() / "demcal_walls_test_plate.stl").string();
  const std::vector<StlTriangle> plate = {{{{{0, 0, 0}, {1000, 0, 0}, {1000, 1000, 0}}}},
                                          {{{{0, 0, 0}, {1000, 1000, 0}, {0, 1000, 0}}}}};
  std::string error;
  REQUIRE(WriteBinaryStl(path, plate, &error));
  Wall wall("plate", 0, PlaneSurface{});
  MeshWallOptions millimetres;
  millimetres.stl.scale = 0.001;
  REQUIRE(ReadMeshWall(path, millimetres, &wall, &error));
  const MeshRef& mesh = std::get<MeshRef>(wall.shape);
  CHECK(mesh.source == path);
  CHECK(mesh.mesh->NumTriangles() == 2);
  CHECK(mesh.mesh->NumPatches() == 1);
  CHECK(mesh.mesh->Area() == Approx(1.0));
  CHECK(wall.name == "plate");
  CHECK(ValidationError(wall) == "valid");

  const std::string missing = path + ".missing";
  CHECK(!ReadMeshWall(missing, {}, &wall, &error));
  CHECK_THAT(error, Catch::StartsWith(missing));
  MeshWallOptions negative;
  negative.stl.scale = -1;
  CHECK(!ReadMeshWall(path, negative, &wall, &error));
  CHECK_THAT(error, Catch::Contains("scale"));
  std::filesystem::remove(path);
}
