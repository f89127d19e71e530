// Checkpoint and restart: a restarted run continues bit-identically (DEM core II).
#include <catch2/catch.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include "core/checkpoint/checkpoint_scene.h"
#include "core/simulation/simulation.h"
#include "core/walls/wall_test_support.h"

using namespace demcal::core;

namespace {

// A file name unique to this process: test processes (ctest --parallel, other builds) share /tmp.
std::string TempPath(const std::string& tag) {
  return (std::filesystem::temp_directory_path() /
          ("demcal_checkpoint_" + tag + "_" + std::to_string(::getpid()) + ".bin"))
      .string();
}

// Everything with state (checkpoint_scene.h), fed from 60–90 mm up, with friction and
// restitution other than the defaults.
Scene RichScene() {
  Scene s = checkpoint_test::PourScene({.box_max_m = {0.03, 0.03, 0.1},
                                        .interfacial_energy_J_m2 = 0.02,
                                        .feed_radius_m = 0.012,
                                        .feed_z_lo_m = 0.06,
                                        .feed_z_hi_m = 0.09,
                                        .feed_rate_kg_s = 0.01,
                                        .seed = 11});
  s.pair_parameters[0].sliding_friction = 0.5;
  s.pair_parameters[0].restitution = 0.4;
  return s;
}

}  // namespace

TEST_CASE("a restarted run continues bit-identically", "[unit][checkpoint]") {
  const std::string path =
      TempPath("a");
  std::string err;
  Simulation reference(RichScene(), {.threads = 2});
  REQUIRE(reference.Initialize(&err));
  REQUIRE(reference.Run(0.15).ok());
  REQUIRE(reference.SaveCheckpoint(path, &err));
  REQUIRE(reference.Run(0.1).ok());
  REQUIRE(reference.system().clumps.Size() > 0);
  REQUIRE(reference.ActiveContacts() > 0);

  Simulation restarted(RichScene(), {.threads = 1});
  REQUIRE(restarted.Initialize(&err));
  REQUIRE(restarted.LoadCheckpoint(path, &err));
  REQUIRE(restarted.Run(0.1).ok());

  REQUIRE(restarted.particles().Size() == reference.particles().Size());
  CHECK(restarted.time_s() == reference.time_s());
  CHECK(restarted.particles().position_m == reference.particles().position_m);
  CHECK(restarted.particles().velocity_m_s == reference.particles().velocity_m_s);
  CHECK(restarted.particles().angular_velocity_rad_s == reference.particles().angular_velocity_rad_s);
  CHECK(restarted.FactoryReports()[0].inserted_mass_kg ==
        reference.FactoryReports()[0].inserted_mass_kg);
  std::remove(path.c_str());
}

TEST_CASE("a checkpoint of another scene or a corrupt file is refused", "[unit][checkpoint]") {
  const std::string path =
      TempPath("b");
  std::string err;
  Simulation a(RichScene(), {.threads = 1});
  REQUIRE(a.Initialize(&err));
  REQUIRE(a.Run(0.01).ok());
  REQUIRE(a.SaveCheckpoint(path, &err));
  Scene other = RichScene();
  other.seed = 12;
  Simulation b(other, {.threads = 1});
  REQUIRE(b.Initialize(&err));
  CHECK_FALSE(b.LoadCheckpoint(path, &err));
  CHECK_THAT(err, Catch::Contains("written for another scene: seed differs"));
  {  // truncate it
    std::ifstream in(path, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), {});
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), bytes.size() / 2);
  }
  Simulation c(RichScene(), {.threads = 1});
  REQUIRE(c.Initialize(&err));
  CHECK_FALSE(c.LoadCheckpoint(path, &err));
  CHECK_THAT(err, Catch::Contains("truncated"));
  std::remove(path.c_str());
}

TEST_CASE("a restart with mesh and moving walls continues bit-identically", "[unit][checkpoint]") {
  // Spheres poured into a mesh box (several mesh contacts per sphere, each with its history)
  // onto a mesh plate that starts to slide, beside a rising cylinder.
  const std::string path =
      TempPath("mesh");
  Scene s = RichScene();
  s.walls = {wall_test::MeshBox("box", {0, 0, 0}, {0.03, 0.03, 0.1}, /*open_top=*/true)};
  Wall plate = wall_test::MeshPlate("plate", 0.008, 0);
  std::get<MeshRef>(plate.shape).offset_m = {0.015, 0.015, 0.005};
  plate.velocity_m_s = {0.02, 0.01, 0};
  plate.motion_start_s = 0.12;
  s.walls.push_back(plate);
  Wall post("post", 0, CylinderSurface{.axis_point_m = {0.004, 0.004, 0}, .radius_m = 0.002,
                                       .inside = false});
  post.velocity_m_s = {0, 0, 0.05};
  s.walls.push_back(post);
  std::string err;
  Simulation reference(s, {.threads = 2});
  REQUIRE(reference.Initialize(&err));
  REQUIRE(reference.Run(0.15).ok());
  REQUIRE(reference.SaveCheckpoint(path, &err));
  REQUIRE(reference.Run(0.1).ok());

  Simulation restarted(s, {.threads = 1});
  REQUIRE(restarted.Initialize(&err));
  REQUIRE(restarted.LoadCheckpoint(path, &err));
  REQUIRE(restarted.Run(0.1).ok());
  CHECK(restarted.particles().position_m == reference.particles().position_m);
  CHECK(restarted.particles().angular_velocity_rad_s ==
        reference.particles().angular_velocity_rad_s);
  CHECK(restarted.ActiveContacts() == reference.ActiveContacts());
  CHECK(std::get<MeshRef>(restarted.walls()[1].shape).offset_m ==
        std::get<MeshRef>(reference.walls()[1].shape).offset_m);
  const std::vector<WallLoad> a = reference.WallLoads(), b = restarted.WallLoads();
  for (size_t w = 0; w < a.size(); ++w) {
    CHECK(a[w].force_N == b[w].force_N);
    CHECK(a[w].torque_N_m == b[w].torque_N_m);
  }
  CHECK(Norm(a[0].force_N) > 0);
  CHECK(Norm(a[1].force_N) > 0);
  std::remove(path.c_str());
}
