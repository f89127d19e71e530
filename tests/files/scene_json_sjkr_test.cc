// The scene file's sjkr key, interactions.*.cohesion_energy_density_J_m3: read per pair, ranged
// with its unit, and refused together with JKR's Γ on another pair (a scene runs one normal law,
// core/contact/normal_model.h).
#include <catch2/catch.hpp>
#include <fstream>
#include <variant>

#include "core/contact/normal_model.h"
#include "files/scene_json.h"
#include "tests/files/pour_box_document.h"
#include "workflow/test_paths.h"

using namespace demcal::workflow;
using demcal::testing::PourBoxDocument;
using nlohmann::json;

namespace {

// Parses `document` into `file` and returns the error ("" if it parsed).
std::string Parse(const json& document, SceneFile* file) {
  std::string error;
  return ParseSceneJson(document, "scene.json", file, &error) ? "" : error;
}

}  // namespace

TEST_CASE("a pair's sjkr cohesion energy density is read and selects the sjkr law", "[unit]") {
  json d = PourBoxDocument();
  d["interactions"]["pairs"][0]["cohesion_energy_density_J_m3"] = 7500.0;
  SceneFile file;
  REQUIRE(Parse(d, &file).empty());
  const auto& pairs = file.scene.pair_parameters;  // glass, steel
  REQUIRE(pairs.size() == 4);
  CHECK(pairs[0].cohesion_energy_density_J_m3 == 0);
  CHECK(pairs[1].cohesion_energy_density_J_m3 == 7500.0);
  CHECK(pairs[2].cohesion_energy_density_J_m3 == 7500.0);
  CHECK(std::holds_alternative<demcal::core::SjkrNormal>(
      demcal::core::SelectNormalModel(pairs)));
}

TEST_CASE("a bad sjkr cohesion energy density is refused naming file, field and range",
          "[unit]") {
  json d = PourBoxDocument();
  SceneFile file;
  d["interactions"]["default"]["cohesion_energy_density_J_m3"] = -1.0;
  std::string error = Parse(d, &file);
  CHECK_THAT(error, Catch::StartsWith("scene.json: "));
  CHECK_THAT(error, Catch::Contains("field 'interactions.default.cohesion_energy_density_J_m3' = "
                                    "-1 is outside the allowed range [0, 1e+09] J/m3"));
  d["interactions"]["default"]["cohesion_energy_density_J_m3"] = "strong";
  CHECK_THAT(Parse(d, &file),
             Catch::Contains("field 'interactions.default.cohesion_energy_density_J_m3' must be "
                             "a number"));
}

TEST_CASE("a scene whose pairs call for both JKR and sjkr is refused with both named", "[unit]") {
  json d = PourBoxDocument();
  d["interactions"]["default"]["interfacial_energy_J_m2"] = 0.01;
  d["interactions"]["pairs"][0]["cohesion_energy_density_J_m3"] = 7500.0;
  SceneFile file;
  const std::string error = Parse(d, &file);
  CHECK_THAT(error, Catch::StartsWith("scene.json: "));
  CHECK_THAT(error, Catch::Contains("field 'interactions' calls for two normal laws, jkr (first at "
                                    "interactions[glass,glass]) and sjkr (first at "
                                    "interactions[glass,steel])"));
}
