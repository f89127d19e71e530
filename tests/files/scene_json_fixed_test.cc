// particles[].fixed in scene files: a frozen base can be loaded from a file, the
// spheres marked fixed stay where they are under gravity, and bad values are refused by name.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>

#include "core/simulation/simulation.h"
#include "files/scene_json.h"
#include "tests/files/pour_box_document.h"
#include "workflow/test_paths.h"

using namespace demcal::workflow;
using demcal::testing::PourBoxDocument;
using nlohmann::json;

namespace {

std::string ErrorOf(const json& document) {
  SceneFile file;
  std::string error;
  return ParseSceneJson(document, "scene.json", &file, &error) ? "" : error;
}

}  // namespace

TEST_CASE("particles marked fixed are read and stay in place in a run", "[unit]") {
  json d = PourBoxDocument();
  d.erase("factories");
  d.erase("fills");
  d["particles"] = json::parse(R"([
      {"species": "beads", "position_m": [0.02, 0.02, 0.01], "fixed": true},
      {"species": "beads", "position_m": [0.03, 0.02, 0.01], "fixed": false},
      {"species": "beads", "position_m": [0.035, 0.02, 0.01]}])");
  SceneFile file;
  std::string error;
  REQUIRE(ParseSceneJson(d, "scene.json", &file, &error));
  REQUIRE(file.scene.particles.size() == 3);
  CHECK(file.scene.particles[0].fixed);
  CHECK_FALSE(file.scene.particles[1].fixed);
  CHECK_FALSE(file.scene.particles[2].fixed);

  demcal::core::Simulation sim(file.scene, {.threads = 1});
  REQUIRE(sim.Initialize(&error));
  REQUIRE(sim.Run(0.02).ok());
  // Slots are reordered (moving spheres first): find the one that has not fallen.
  int unmoved = 0;
  for (size_t i = 0; i < sim.particles().Size(); ++i)
    unmoved += sim.particles().position_m[i].z == 0.01 && sim.particles().position_m[i].x == 0.02;
  CHECK(unmoved == 1);
  for (size_t i = 0; i < sim.particles().Size(); ++i)
    if (sim.particles().position_m[i].x != 0.02) CHECK(sim.particles().position_m[i].z < 0.01);
}

TEST_CASE("a non-boolean fixed is refused naming the field", "[unit]") {
  json d = PourBoxDocument();
  d["particles"] = json::parse(R"([{"species": "beads", "position_m": [0.02, 0.02, 0.1],
      "fixed": 1}])");
  CHECK_THAT(ErrorOf(d), Catch::Contains("particles[0].fixed"));
}
