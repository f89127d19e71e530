#include "files/scene_json.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>

#include "tests/files/pour_box_document.h"
#include "workflow/test_paths.h"

using namespace demcal::workflow;
using demcal::testing::RepoRoot;
using demcal::testing::PourBoxDocument;
using nlohmann::json;

namespace {

std::string Example(const std::string& relative) {
  return (RepoRoot() / "examples" / relative).string();
}

// Parses `document` and returns the error ("" if it parsed).
std::string ErrorOf(const json& document) {
  SceneFile file;
  std::string error;
  return ParseSceneJson(document, "scene.json", &file, &error) ? "" : error;
}

}  // namespace

TEST_CASE("the pour_box example parses into the scene it describes", "[unit]") {
  SceneFile file;
  std::string error;
  REQUIRE(LoadSceneFile(Example("pour_box.json"), &file, &error));
  const demcal::core::Scene& s = file.scene;
  CHECK(s.seed == 42);
  REQUIRE(s.materials.size() == 2);
  CHECK(s.materials[0].name == "glass");
  CHECK(s.materials[0].density_kg_m3 == 2500);
  CHECK(s.materials[1].density_kg_m3 == 0);  // wall-only material
  REQUIRE(s.species.size() == 1);
  CHECK(s.species[0].size.kind == demcal::core::SizeDistribution::Kind::kUniform);
  CHECK(s.species[0].size.min_diameter_m == 0.0018);
  CHECK(s.species[0].size.max_diameter_m == 0.0022);
  // Pair override (glass, steel) is symmetric; (glass, glass) keeps the default.
  REQUIRE(s.pair_parameters.size() == 4);
  CHECK(s.pair_parameters[0].sliding_friction == 0.5);
  CHECK(s.pair_parameters[0].rolling_friction == 0.1);
  CHECK(s.pair_parameters[1].sliding_friction == 0.3);
  CHECK(s.pair_parameters[2].sliding_friction == 0.3);
  CHECK(s.pair_parameters[2].restitution == 0.6);
  CHECK(s.pair_parameters[2].rolling_friction == 0.1);  // not overridden: from the default
  CHECK(s.pair_parameters[3].sliding_friction == 0.5);
  CHECK(s.rolling.name == "epsd2");
  CHECK(s.walls.size() == 5);  // open-top box
  REQUIRE(s.fills.size() == 1);
  CHECK(s.fills[0].count == 3000);
  CHECK(s.fills[0].velocity_m_s.z == -0.5);
  CHECK(s.time.duration_s == 0.5);
  CHECK(file.output.vtk_interval_s == 0.05);
  CHECK(!file.description.empty());
}

TEST_CASE("shear moduli become Young's moduli and plane normals are normalised", "[unit]") {
  json d = PourBoxDocument();
  d["materials"][0].erase("youngs_modulus_Pa");
  d["materials"][0]["shear_modulus_Pa"] = 2e6;
  d["walls"] = json::parse(R"([{"type": "plane", "point_m": [0, 0, 0], "normal": [0, 0, 2],
                               "material": "steel", "velocity_m_s": [0, 0, 0.1]}])");
  SceneFile file;
  std::string error;
  REQUIRE(ParseSceneJson(d, "scene.json", &file, &error));
  CHECK(file.scene.materials[0].youngs_modulus_Pa == Approx(2 * 2e6 * 1.25));
  REQUIRE(file.scene.walls.size() == 1);
  CHECK(std::get<demcal::core::PlaneSurface>(file.scene.walls[0].shape).normal.z == 1.0);
  CHECK(file.scene.walls[0].velocity_m_s.z == 0.1);
  CHECK(file.scene.walls[0].name == "walls[0]");
}

TEST_CASE("cylinder, cone and mesh walls are read with motion and load point", "[unit]") {
  namespace core = demcal::core;
  json d = PourBoxDocument();
  d["walls"] = json::parse(R"([
    {"type": "cylinder", "name": "silo", "material": "steel", "axis_point_m": [0.02, 0.02, 0],
     "axis": [0, 0, 3], "radius_m": 0.015, "axial_max_m": 0.1, "velocity_m_s": [0, 0, 0.01],
     "motion_start_s": 0.1, "motion_end_s": 0.5, "load_point_m": [0.02, 0.02, 0]},
    {"type": "cone", "material": "steel", "axis_point_m": [0.02, 0.02, 0.05], "axis": [0, 0, 1],
     "height0_m": 0, "radius0_m": 0.005, "height1_m": 0.03, "radius1_m": 0.018,
     "inside": true, "shell": false},
    {"type": "mesh", "name": "cube", "material": "steel", "file": "cube_10mm_ascii.stl",
     "scale": 0.001, "offset_m": [0.01, 0.01, 0.02]}])");
  SceneFile file;
  std::string error;
  const std::string source = (RepoRoot() / "tests" / "data" / "scene.json").string();
  REQUIRE(ParseSceneJson(d, source, &file, &error));
  REQUIRE(file.scene.walls.size() == 3);
  const core::Wall& silo = file.scene.walls[0];
  CHECK(silo.name == "silo");
  const auto& cyl = std::get<core::CylinderSurface>(silo.shape);
  CHECK(cyl.axis.z == 1.0);
  CHECK(cyl.radius_m == 0.015);
  CHECK(std::isinf(cyl.axial_min_m));
  CHECK(cyl.axial_max_m == 0.1);
  CHECK(cyl.inside);
  CHECK(silo.shell);
  CHECK(silo.velocity_m_s.z == 0.01);
  CHECK(silo.motion_start_s == 0.1);
  CHECK(silo.motion_end_s == 0.5);
  CHECK(silo.load_point_m.x == 0.02);
  const core::Wall& funnel = file.scene.walls[1];
  CHECK(funnel.name == "walls[1]");
  const auto& cone = std::get<core::ConeFrustumSurface>(funnel.shape);
  CHECK(cone.radius0_m == 0.005);
  CHECK(cone.height1_m == 0.03);
  CHECK(!funnel.shell);
  CHECK(funnel.motion_start_s == 0);
  CHECK(std::isinf(funnel.motion_end_s));
  const auto& mesh = std::get<core::MeshRef>(file.scene.walls[2].shape);
  REQUIRE(mesh.mesh);
  CHECK(mesh.offset_m.z == 0.02);
  CHECK(mesh.source.find("cube_10mm_ascii.stl") != std::string::npos);
}

TEST_CASE("bad cylinder, cone and mesh walls are rejected naming the field", "[unit]") {
  auto error_of = [](const char* walls) {
    json d = PourBoxDocument();
    d["walls"] = json::parse(walls);
    SceneFile file;
    std::string error;
    const std::string source = (RepoRoot() / "tests" / "data" / "scene.json").string();
    return ParseSceneJson(d, source, &file, &error) ? std::string() : error;
  };
  CHECK_THAT(error_of(R"([{"type": "cylinder", "material": "steel", "axis_point_m": [0, 0, 0],
                           "axis": [0, 0, 0], "radius_m": 0.01}])"),
             Catch::Contains("field 'walls[0].axis' must be a non-zero vector"));
  CHECK_THAT(error_of(R"([{"type": "cylinder", "material": "steel", "axis_point_m": [0, 0, 0],
                           "axis": [0, 0, 1], "radius_m": -0.01}])"),
             Catch::Contains("field 'walls[0].radius_m' = -0.01 is outside the allowed range"));
  CHECK_THAT(error_of(R"([{"type": "cone", "material": "steel", "axis_point_m": [0, 0, 0],
                           "axis": [0, 0, 1], "height0_m": 0, "radius0_m": -1,
                           "height1_m": 1, "radius1_m": 1}])"),
             Catch::Contains("field 'walls[0].radius0_m' = -1 is outside the allowed range"));
  CHECK_THAT(error_of(R"([{"type": "cone", "material": "steel", "axis_point_m": [0, 0, 0],
                           "axis": [0, 0, 1], "height0_m": 0, "radius0_m": 0.01,
                           "height1_m": 0.02, "radius1_m": 0.02, "radius_m": 1}])"),
             Catch::Contains("unknown key 'walls[0].radius_m'"));
  const std::string missing = error_of(
      R"([{"type": "mesh", "material": "steel", "file": "no_such_file.stl"}])");
  CHECK_THAT(missing, Catch::Contains("field 'walls[0].file'"));
  CHECK_THAT(missing, Catch::Contains("no_such_file.stl"));
  CHECK_THAT(error_of(R"([{"type": "mesh", "material": "steel", "file": "cube_10mm_ascii.stl",
                           "scale": 0}])"),
             Catch::Contains("field 'walls[0].scale' = 0 is outside the allowed range"));
  CHECK_THAT(error_of(R"([{"type": "plane", "material": "steel", "point_m": [0, 0, 0],
                           "normal": [0, 0, 1], "motion_start_s": 2, "motion_end_s": 1}])"),
             Catch::Contains("field 'walls[0].motion_end_s' must not be before"));
}

TEST_CASE("periodic axes are read per axis and checked against gravity by the core", "[unit]") {
  json d = PourBoxDocument();
  d["walls"] = json::array();
  d["walls"].push_back(json::parse(
      R"({"type": "plane", "point_m": [0, 0, 0], "normal": [0, 0, 1], "material": "steel"})"));
  d["periodic"] = json::parse(R"({"x": true, "y": true})");
  SceneFile file;
  std::string error;
  REQUIRE(ParseSceneJson(d, "scene.json", &file, &error));
  CHECK(file.scene.periodic[0]);
  CHECK(file.scene.periodic[1]);
  CHECK_FALSE(file.scene.periodic[2]);
  d["periodic"]["z"] = true;
  CHECK_THAT(ErrorOf(d), Catch::Contains("field 'periodic.z': a periodic axis must be "
                                         "perpendicular to gravity"));
  d["periodic"] = json::parse(R"({"x": 1})");
  CHECK_THAT(ErrorOf(d), Catch::Contains("field 'periodic.x' must be true or false"));
}

TEST_CASE("explicit particles and diameter tables are read", "[unit]") {
  json d = PourBoxDocument();
  d["species"].push_back(json::parse(R"({"name": "mix", "material": "glass",
      "diameter_table": [{"diameter_m": 0.001, "number_fraction": 0.25},
                         {"diameter_m": 0.002, "number_fraction": 0.75}]})"));
  d["particles"] = json::parse(R"([{"species": "mix", "position_m": [0.02, 0.02, 0.1],
      "velocity_m_s": [0, 0, -1], "angular_velocity_rad_s": [0, 3, 0], "diameter_m": 0.002}])");
  SceneFile file;
  std::string error;
  REQUIRE(ParseSceneJson(d, "scene.json", &file, &error));
  REQUIRE(file.scene.particles.size() == 1);
  CHECK(file.scene.particles[0].species == 1);
  CHECK(file.scene.particles[0].angular_velocity_rad_s.y == 3);
  CHECK(file.scene.species[1].size.table_number_fraction[1] == 0.75);
}

TEST_CASE("clump shapes are read as explicit spheres or from an ellipsoid", "[unit]") {
  json d = PourBoxDocument();
  d["species"][0]["clump"] = json::parse(
      R"({"spheres": [{"centre": [-0.5, 0, 0], "radius": 0.6}, {"centre": [0.5, 0, 0], "radius": 0.6}]})");
  d["species"].push_back(json::parse(R"({"name": "rods", "material": "glass", "diameter_m": 0.002,
      "clump": {"ellipsoid": {"semi_axes": [3, 1, 1], "sphere_count": 4}}})"));
  d["particles"] = json::parse(R"([{"species": "rods", "position_m": [0.02, 0.02, 0.1],
      "orientation": [2, 0, 0, 0]}])");
  SceneFile file;
  std::string error;
  REQUIRE(ParseSceneJson(d, "scene.json", &file, &error));
  REQUIRE(file.scene.species[0].clump_shape.size() == 2);
  CHECK(file.scene.species[0].clump_shape[1].centre.x == 0.5);
  CHECK(file.scene.species[0].clump_shape[1].radius == 0.6);
  CHECK(file.scene.species[1].clump_shape.size() == 4);
  CHECK(file.scene.particles[0].orientation.w == 1.0);  // normalised

  json plain = PourBoxDocument();
  plain["particles"] = json::parse(R"([{"species": "beads", "position_m": [0.02, 0.02, 0.1],
      "orientation": [1, 0, 0, 0]}])");
  CHECK_THAT(ErrorOf(plain), Catch::Contains("'particles[0].orientation' applies only to clump "
                                             "species ('beads' is a plain sphere)"));
  json bad_axes = d;
  bad_axes["species"][1]["clump"]["ellipsoid"]["semi_axes"] = json::array({1, 3, 1});
  CHECK_THAT(ErrorOf(bad_axes), Catch::Contains("'species[1].clump.ellipsoid.semi_axes' must be "
                                                "[a, b, c] with a >= b >= c > 0"));
  json zero_radius = d;
  zero_radius["species"][0]["clump"]["spheres"][1]["radius"] = 0;
  CHECK_THAT(ErrorOf(zero_radius),
             Catch::Contains("'species[0].clump.spheres[1].radius' = 0 is outside"));
}

TEST_CASE("factories are read with box or cylinder regions and mass fractions", "[unit]") {
  json d = PourBoxDocument();
  d["species"].push_back(
      json::parse(R"({"name": "fines", "material": "glass", "diameter_m": 0.0015})"));
  d["factories"] = json::parse(R"([
    {"name": "hopper", "species": [{"name": "beads", "mass_fraction": 0.7},
                                   {"name": "fines", "mass_fraction": 0.3}],
     "region": {"min_m": [0.005, 0.005, 0.08], "max_m": [0.035, 0.035, 0.11]},
     "mass_rate_kg_s": 0.01, "start_s": 0.1, "end_s": 0.3, "velocity_m_s": [0, 0, -0.2]},
    {"species": [{"name": "beads"}], "mass_rate_kg_s": 0.005, "total_mass_kg": 0.001,
     "region": {"shape": "cylinder", "axis_point_m": [0.02, 0.02, 0], "radius_m": 0.01,
                "z_range_m": [0.08, 0.11]}}])");
  SceneFile file;
  std::string error;
  REQUIRE(ParseSceneJson(d, "scene.json", &file, &error));
  REQUIRE(file.scene.factories.size() == 2);
  const auto& hopper = file.scene.factories[0];
  CHECK(hopper.name == "hopper");
  CHECK(hopper.species == std::vector<int>{0, 1});
  CHECK(hopper.mass_fractions == std::vector<double>{0.7, 0.3});
  CHECK(hopper.end_s == 0.3);
  CHECK(hopper.velocity_m_s.z == -0.2);
  const auto& tube = file.scene.factories[1];
  CHECK(tube.name == "factories[1]");
  CHECK(tube.mass_fractions == std::vector<double>{1.0});
  CHECK(tube.region.shape == demcal::core::InsertionRegion::Shape::kCylinder);
  CHECK(tube.region.radius_m == 0.01);
  CHECK(tube.total_mass_kg == 0.001);

  json missing_fraction = d;
  missing_fraction["factories"][0]["species"][1].erase("mass_fraction");
  CHECK_THAT(ErrorOf(missing_fraction),
             Catch::Contains("missing required field 'factories[0].species[1].mass_fraction'"));
  json unknown = d;
  unknown["factories"][1]["species"][0]["name"] = "sand";
  CHECK_THAT(ErrorOf(unknown),
             Catch::Contains("'factories[1].species[0].name' = 'sand' names no species"));
  json sum = d;
  sum["factories"][0]["species"][1]["mass_fraction"] = 0.2;
  CHECK_THAT(ErrorOf(sum), Catch::Contains("'factories[0].species' mass fractions must sum to 1"));
  json rate = d;
  rate["factories"][0]["mass_rate_kg_s"] = 0;
  CHECK_THAT(ErrorOf(rate), Catch::Contains("'factories[0].mass_rate_kg_s' = 0 kg/s is outside"));
}

TEST_CASE("each kind of bad input gives an error naming the file and the field", "[unit]") {
  struct Case {
    const char* what;
    const char* pointer;  // JSON pointer to set ("" with op erase below)
    json value;
    const char* expected;
  };
  const std::vector<Case> cases = {
      {"unknown key", "/materials/0/densty_kg_m3", 1000,
       "unknown key 'materials[0].densty_kg_m3' (did you mean 'density_kg_m3'?)"},
      {"unknown top-level key", "/gravity", json::array({0, 0, -9.81}), "unknown key 'gravity'"},
      {"wrong type", "/fills/0/count", "3000", "field 'fills[0].count' must be an integer"},
      {"wrong vector length", "/domain/max_m", json::array({1, 1}),
       "field 'domain.max_m' must be an array of 3 numbers"},
      {"out of range (JSON layer)", "/materials/0/poisson_ratio", 0.7,
       "field 'materials[0].poisson_ratio' = 0.7 is outside the allowed range (-1, 0.5)"},
      {"out of range (core check)", "/time/duration_s", -1.0,
       "field 'time.duration_s' = -1 s is outside the allowed range"},
      {"out of range pair override", "/interactions/pairs/0/restitution", 1.5,
       "field 'interactions.pairs[0].restitution' = 1.5 is outside the allowed range (0, 1]"},
      {"unknown material", "/species/0/material", "glas",
       "field 'species[0].material' = 'glas' names no material (defined: glass, steel)"},
      {"unknown material in a pair", "/interactions/pairs/0/materials/1", "iron",
       "field 'interactions.pairs[0].materials[1]' = 'iron' names no material"},
      {"unknown species", "/fills/0/species", "sand",
       "field 'fills[0].species' = 'sand' names no species (defined: beads)"},
      {"unknown rolling model", "/contact_model/rolling", "epsd3",
       "field 'contact_model.rolling' = 'epsd3' is not one of none|cdt|cdt_relative|epsd|epsd2"},
      {"damping without epsd", "/contact_model/epsd_damping_ratio", 0.3,
       "field 'contact_model.epsd_damping_ratio' applies only to rolling = \"epsd\""},
      {"wrong format", "/format", "demcal-scene/2",
       "field 'format' = 'demcal-scene/2' is not supported"},
      {"box with max below min", "/walls/0/max_m", json::array({0.04, 0.04, -1}),
       "field 'walls[0].max_m' must exceed 'walls[0].min_m' on every axis"},
      {"box key on a plane", "/walls/0/type", "plane", "unknown key 'walls[0].max_m'"},
      {"bad range order", "/species/0/diameter_range_m", json::array({0.003, 0.002}),
       "field 'species[0].diameter_range_m' = [0.003000, 0.002000] must satisfy 0 < min <= max"},
      {"both time step settings", "/time/timestep_s", 1e-5,
       "field 'time.timestep_s' cannot be given together with 'time.rayleigh_fraction'"},
      {"vtk interval zero", "/output/vtk_interval_s", 0,
       "field 'output.vtk_interval_s' = 0 is outside the allowed range (0, 1e+06] s"},
      {"negative seed", "/seed", -3, "field 'seed' must be a non-negative integer"},
      {"fill outside the domain", "/fills/0/region/max_m", json::array({0.039, 0.039, 0.5}),
       "field 'fills[0].region' must lie inside the domain"},
  };
  for (const Case& c : cases) {
    INFO(c.what);
    json d = PourBoxDocument();
    d[json::json_pointer(c.pointer)] = c.value;
    const std::string error = ErrorOf(d);
    CHECK_THAT(error, Catch::StartsWith("scene.json: "));
    CHECK_THAT(error, Catch::Contains(c.expected));
  }
}

TEST_CASE("missing fields, conflicting alternatives and zero normals are rejected by name",
          "[unit]") {
  auto without = [](const char* pointer) {
    json d = PourBoxDocument();
    const json::json_pointer p(pointer);
    d[p.parent_pointer()].erase(p.back());
    return ErrorOf(d);
  };
  CHECK_THAT(without("/seed"), Catch::Contains("missing required field 'seed'"));
  CHECK_THAT(without("/time/duration_s"),
             Catch::Contains("missing required field 'time.duration_s'"));
  CHECK_THAT(without("/materials/0/poisson_ratio"),
             Catch::Contains("missing required field 'materials[0].poisson_ratio'"));
  CHECK_THAT(without("/materials/0/youngs_modulus_Pa"),
             Catch::Contains("'materials[0].youngs_modulus_Pa' is missing: give exactly one of"));
  CHECK_THAT(without("/materials/0/density_kg_m3"),
             Catch::Contains("field 'materials[0].density_kg_m3' is required (> 0) because "
                             "species 'beads'"));
  CHECK_THAT(without("/species/0/diameter_range_m"),
             Catch::Contains("'species[0].diameter_m' is missing: give exactly one of"));
  CHECK_THAT(without("/fills"), Catch::Contains("the scene places no particles"));

  json both = PourBoxDocument();
  both["materials"][0]["shear_modulus_Pa"] = 1e6;
  CHECK_THAT(ErrorOf(both), Catch::Contains("'materials[0].shear_modulus_Pa' cannot be given "
                                            "together with 'youngs_modulus_Pa'"));
  json zero = PourBoxDocument();
  zero["walls"].push_back(json::parse(
      R"({"type": "plane", "point_m": [0, 0, 0], "normal": [0, 0, 0], "material": "steel"})"));
  CHECK_THAT(ErrorOf(zero), Catch::Contains("field 'walls[1].normal' must be a non-zero vector"));
  json twice = PourBoxDocument();
  twice["interactions"]["pairs"].push_back(
      json::parse(R"({"materials": ["steel", "glass"], "restitution": 0.9})"));
  CHECK_THAT(ErrorOf(twice), Catch::Contains("'interactions.pairs[1].materials' repeats the pair"));
  json same_name = PourBoxDocument();
  same_name["materials"][1]["name"] = "glass";
  CHECK_THAT(ErrorOf(same_name), Catch::Contains("'materials[1].name' = 'glass' is used twice"));
}

TEST_CASE("JSON syntax errors give line and column; duplicate keys are rejected", "[unit]") {
  SceneFile file;
  std::string error;
  CHECK_FALSE(ParseSceneText("{\n  \"seed\": 1,\n}", "s.json", &file, &error));
  CHECK_THAT(error, Catch::StartsWith("s.json: invalid JSON: parse error at line 3, column 1"));
  CHECK_FALSE(ParseSceneText(R"({"seed": 1, "seed": 2})", "s.json", &file, &error));
  CHECK(error == "s.json: seed: key 'seed' appears twice in one object; JSON keys must be unique");
  CHECK_FALSE(LoadSceneFile("/nonexistent/scene.json", &file, &error));
  CHECK_THAT(error, Catch::StartsWith("/nonexistent/scene.json: cannot read the scene file: "));
}

TEST_CASE("every file in examples/invalid is rejected with an error naming its field", "[unit]") {
  const std::map<std::string, std::string> expected = {
      {"bad_restitution.json",
       "'interactions.default.restitution' = 0 is outside the allowed range (0, 1]"},
      {"bad_syntax.json", "invalid JSON: parse error at line 5"},
      {"missing_field.json", "missing required field 'time.duration_s'"},
      {"out_of_range.json",
       "'materials[0].poisson_ratio' = 0.7 is outside the allowed range (-1, 0.5)"},
      {"unknown_key.json", "unknown key 'materials[0].densty_kg_m3'"},
      {"unknown_material.json", "'species[0].material' = 'glas' names no material"},
      {"wrong_type.json", "'fills[0].count' must be an integer, got string \"50\""},
      {"zero_normal.json", "'walls[0].normal' must be a non-zero vector"},
  };
  std::set<std::string> seen;
  for (const auto& entry : std::filesystem::directory_iterator(RepoRoot() / "examples/invalid")) {
    const std::string name = entry.path().filename().string();
    INFO(name);
    REQUIRE(expected.count(name) == 1);  // every invalid example has its expectation here
    SceneFile file;
    std::string error;
    CHECK_FALSE(LoadSceneFile(entry.path().string(), &file, &error));
    CHECK_THAT(error, Catch::StartsWith(entry.path().string() + ": "));
    CHECK_THAT(error, Catch::Contains(expected.at(name)));
    seen.insert(name);
  }
  CHECK(seen.size() == expected.size());
}
