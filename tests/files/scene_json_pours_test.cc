// Scene files for pours and discharges: sinks, cylinder fills, walls removed at a
// time, factory regions that move or follow the heap, the mass-vs-time output; bad values are
// refused by name.
#include <catch2/catch.hpp>
#include <fstream>

#include "files/scene_json.h"
#include "workflow/test_paths.h"

using namespace demcal::workflow;
using nlohmann::json;

namespace {

json Example(const char* name) {
  return json::parse(std::ifstream((demcal::testing::RepoRoot() / "examples" / name).string()));
}

std::string ErrorOf(const json& document) {
  SceneFile file;
  std::string error;
  return ParseSceneJson(document, "scene.json", &file, &error) ? "" : error;
}

}  // namespace

TEST_CASE("the silo example reads its sink, cylinder fill, plug removal and mass-flow output",
          "[unit]") {
  SceneFile file;
  std::string error;
  REQUIRE(ParseSceneJson(Example("silo_discharge.json"), "silo.json", &file, &error));
  const demcal::core::Scene& s = file.scene;
  REQUIRE(s.sinks.size() == 1);
  CHECK(s.sinks[0].name == "outlet");
  CHECK(s.sinks[0].normal.z == -1);
  CHECK(s.sinks[0].Contains({0, 0, -0.031}));
  CHECK_FALSE(s.sinks[0].Contains({0, 0, -0.029}));
  REQUIRE(s.fills.size() == 1);
  CHECK(s.fills[0].region.shape == demcal::core::InsertionRegion::Shape::kCylinder);
  CHECK(s.fills[0].region.radius_m == 0.0145);
  CHECK(s.walls.back().name == "plug");
  CHECK(s.walls.back().remove_at_s == 0.15);
  CHECK(std::isinf(s.walls.front().remove_at_s));
  CHECK(file.output.mass_flow_interval_s == 0.01);
  REQUIRE(file.output.mass_flow_planes.size() == 1);
  CHECK(file.output.mass_flow_planes[0].name == "orifice");
}

TEST_CASE("the staged pour example reads a factory that follows the heap", "[unit]") {
  SceneFile file;
  std::string error;
  REQUIRE(ParseSceneJson(Example("staged_pour.json"), "pour.json", &file, &error));
  REQUIRE(file.scene.factories.size() == 1);
  CHECK(file.scene.factories[0].follow_heap_clearance_m == 0.015);
  CHECK(file.scene.factories[0].settled_speed_m_s == 0.05);
  json d = Example("staged_pour.json");
  d["factories"][0]["region_velocity_m_s"] = json::array({0, 0, 0.01});
  REQUIRE(ParseSceneJson(d, "pour.json", &file, &error));
  CHECK(file.scene.factories[0].region_velocity_m_s.z == 0.01);
}

TEST_CASE("bad sinks, regions, removal times and mass-flow settings are refused by name",
          "[unit]") {
  struct Case {
    const char* what;
    const char* example;
    const char* pointer;
    json value;
    const char* expected;
  };
  const std::vector<Case> cases = {
      {"sink shape", "silo_discharge.json", "/sinks/0/shape", "sphere",
       "field 'sinks[0].shape'"},
      {"zero sink normal", "silo_discharge.json", "/sinks/0/normal", json::array({0, 0, 0}),
       "field 'sinks[0].normal' must be a non-zero vector"},
      {"sink named domain", "silo_discharge.json", "/sinks/0/name", "domain",
       "field 'sinks[0].name' must be non-empty and not 'domain'"},
      {"box key on a plane sink", "silo_discharge.json", "/sinks/0/min_m", json::array({0, 0, 0}),
       "unknown key 'sinks[0].min_m'"},
      {"negative removal time", "silo_discharge.json", "/walls/2/remove_at_s", -1.0,
       "field 'walls[2].remove_at_s' = -1"},
      {"cylinder fill without radius", "silo_discharge.json", "/fills/0/region/radius_m", -0.01,
       "field 'fills[0].region.radius_m'"},
      {"mass-flow plane without interval", "silo_discharge.json", "/output/mass_flow_interval_s",
       0, "field 'output.mass_flow_interval_s' = 0"},
      {"zero clearance", "staged_pour.json", "/factories/0/follow_heap/clearance_m", 0,
       "field 'factories[0].follow_heap.clearance_m' = 0"},
      {"negative settled speed", "staged_pour.json", "/factories/0/follow_heap/settled_speed_m_s",
       -1, "field 'factories[0].follow_heap.settled_speed_m_s' = -1"},
  };
  for (const Case& c : cases) {
    INFO(c.what);
    json d = Example(c.example);
    d[json::json_pointer(c.pointer)] = c.value;
    const std::string error = ErrorOf(d);
    CHECK_THAT(error, Catch::StartsWith("scene.json: "));
    CHECK_THAT(error, Catch::Contains(c.expected));
  }
  json d = Example("silo_discharge.json");
  d["sinks"].push_back(d["sinks"][0]);
  CHECK_THAT(ErrorOf(d), Catch::Contains("field 'sinks[1].name' = 'outlet' is used by another sink"));
  d = Example("silo_discharge.json");
  d["output"].erase("mass_flow_interval_s");
  CHECK_THAT(ErrorOf(d), Catch::Contains("needs 'output.mass_flow_interval_s' > 0"));
}
