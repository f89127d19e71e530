#include "workflow/simulation/simulate.h"

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "outputs/exit_codes.h"
#include "workflow/test_paths.h"
#include "workflow/tiny_scene.h"
#include "core/io/legacy_vtk_reader.h"
#include "core/io/scratch_dir.h"

using namespace demcal::workflow;
using demcal::testing::ReadLegacyVtk;
using demcal::testing::RepoRoot;
using demcal::testing::ReadJson;
using demcal::testing::ScratchDir;
using demcal::testing::SimulateQuietly;
using demcal::testing::TinyScene;
using demcal::testing::WriteScene;
using nlohmann::json;

namespace {

int CountLines(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  int n = 0;
  while (std::getline(in, line)) ++n;
  return n;
}

}  // namespace

TEST_CASE("simulate runs a tiny scene and writes summary, snapshots and the final table",
          "[unit]") {
  ScratchDir dir("simulate_ok");
  SimulateOptions o;
  o.scene_path = WriteScene(dir, TinyScene());
  o.out_dir = dir.str("out");
  o.threads = 1;
  std::ostringstream log;
  REQUIRE(RunSimulate(o, log) == kExitOk);

  const json s = ReadJson(dir.str("out/summary.json"));
  CHECK(s["format"] == "demcal-run-summary/1");
  CHECK(s["termination"] == "ok");
  CHECK(s["message"] == "completed");
  CHECK(s["scene"] == o.scene_path);
  CHECK(s["seed"] == 3);
  CHECK(s["threads"] == 1);
  CHECK(s["particles"] == 20);
  REQUIRE(s["wall_loads"].is_array());
  REQUIRE(!s["wall_loads"].empty());
  CHECK(s["wall_loads"][0]["name"].is_string());
  CHECK(s["wall_loads"][0]["force_N"].size() == 3);
  CHECK(s["wall_loads"][0]["torque_N_m"].size() == 3);
  CHECK(s["wall_loads"][0]["point_m"].size() == 3);
  CHECK(s["steps"].get<int64_t>() > 0);
  CHECK(s["simulated_time_s"].get<double>() == Approx(0.02).margin(s["timestep_s"].get<double>()));
  CHECK(s["timestep_s"].get<double>() > 0);
  CHECK(s["final_kinetic_energy_J"].get<double>() >= 0);
  CHECK(s["wall_time_s"].get<double>() >= 0);
  CHECK(s["demcal_version"].is_string());
  CHECK(s["output_error"].is_null());

  // Initial state, one per 5 ms and the final state unless it fell on a snapshot step.
  const int snapshots = s["outputs"]["vtk_snapshots"].get<int>();
  CHECK(snapshots >= 5);
  CHECK(snapshots <= 6);
  const json series = ReadJson(dir.str("out/") + s["outputs"]["vtk_series"].get<std::string>());
  REQUIRE(series["files"].size() == static_cast<size_t>(snapshots));
  const std::string last = series["files"].back()["name"];
  const auto vtk = ReadLegacyVtk(dir.str("out/vtk/" + last));
  CHECK(vtk.points.size() == 3 * 20);
  CHECK(vtk.field_data.at("TIME")[0] == s["simulated_time_s"].get<double>());
  CHECK(CountLines(dir.str("out/final_particles.csv")) == 1 + 20);
  CHECK(s["outputs"]["scene_copy"] == "scene.json");
  CHECK(ReadJson(dir.str("out/scene.json")) == ReadJson(o.scene_path));
  CHECK(log.str().find("ok: completed") != std::string::npos);
}

TEST_CASE("simulate rejects an invalid scene with exit code 2 and still writes summary.json",
          "[unit]") {
  ScratchDir dir("simulate_invalid");
  SimulateOptions o;
  o.scene_path = (RepoRoot() / "examples/invalid/unknown_material.json").string();
  o.out_dir = dir.str("out");
  o.quiet = true;
  std::ostringstream log;
  CHECK(RunSimulate(o, log) == kExitInvalidInput);
  CHECK_THAT(log.str(), Catch::Contains("'species[0].material' = 'glas' names no material"));
  const json s = ReadJson(dir.str("out/summary.json"));
  CHECK(s["termination"] == "invalid_scene");
  CHECK_THAT(s["message"].get<std::string>(), Catch::Contains("species[0].material"));
  CHECK(s["seed"].is_null());
  CHECK(s["steps"] == 0);
  CHECK_FALSE(std::filesystem::exists(dir.str("out/final_particles.csv")));
}

TEST_CASE("simulate reports a failed run with exit code 3 and its reason in summary.json",
          "[unit]") {
  // No walls: the spheres fall out of the domain.
  json scene = TinyScene();
  scene.erase("walls");
  scene["time"]["duration_s"] = 0.2;
  ScratchDir dir("simulate_failed");
  std::string log;
  CHECK(SimulateQuietly(dir, scene, /*threads=*/0, &log) == kExitRunFailed);
  const json s = ReadJson(dir.str("out/summary.json"));
  CHECK(s["termination"] == "particles_lost");
  CHECK_THAT(s["message"].get<std::string>(), Catch::Contains("left the domain"));
  CHECK(s["simulated_time_s"].get<double>() < 0.2);
  CHECK(std::filesystem::exists(dir.str("out/final_particles.csv")));  // where it went wrong
  CHECK_THAT(log, Catch::Contains("run failed (particles_lost)"));
}

TEST_CASE("simulate options are validated before anything runs", "[unit]") {
  SimulateOptions o;
  std::string error;
  CHECK_FALSE(o.IsValid(&error));
  o.scene_path = "a.json";
  o.out_dir = "out";
  CHECK(o.IsValid(&error));
  o.threads = -1;
  CHECK_FALSE(o.IsValid(&error));
  CHECK_THAT(error, Catch::Contains("--threads"));
  std::ostringstream log;
  CHECK(RunSimulate(o, log) == kExitInvalidInput);
}

TEST_CASE("the pour_box example places its 3000 spheres and steps without failure", "[unit]") {
  // The full example (0.5 s) takes ~10 s on 2 cores; its first 2 ms check the setup.
  json scene = json::parse(std::ifstream(RepoRoot() / "examples/pour_box.json"));
  scene["time"]["duration_s"] = 0.002;
  ScratchDir dir("simulate_pour_box");
  REQUIRE(SimulateQuietly(dir, scene) == kExitOk);
  const json s = ReadJson(dir.str("out/summary.json"));
  CHECK(s["particles"] == 3000);
  CHECK(s["termination"] == "ok");
  CHECK(CountLines(dir.str("out/final_particles.csv")) == 1 + 3000);
}

TEST_CASE("simulate runs clumps fed by a factory and reports the factory", "[unit]") {
  json scene = TinyScene();
  scene["species"][0]["clump"] =
      json::parse(R"({"ellipsoid": {"semi_axes": [1.5, 1, 1], "sphere_count": 2}})");
  scene["domain"]["max_m"] = json::array({0.02, 0.02, 0.04});
  scene["walls"][0]["max_m"] = json::array({0.02, 0.02, 0.04});
  scene["factories"] = json::parse(R"([{"name": "top", "species": [{"name": "beads"}],
      "mass_rate_kg_s": 0.002,
      "region": {"min_m": [0.002, 0.002, 0.025], "max_m": [0.018, 0.018, 0.038]}}])");
  scene["time"]["duration_s"] = 0.05;
  ScratchDir dir("simulate_factory");
  REQUIRE(SimulateQuietly(dir, scene) == kExitOk);
  const json s = ReadJson(dir.str("out/summary.json"));
  CHECK(s["termination"] == "ok");
  REQUIRE(s["factories"].size() == 1);
  CHECK(s["factories"][0]["name"] == "top");
  const int64_t inserted = s["factories"][0]["particles"].get<int64_t>();
  CHECK(inserted > 0);
  CHECK(s["particles"].get<int64_t>() == 20 + inserted);  // bodies: clumps count once
  CHECK(s["outputs"]["final_clumps_csv"] == "final_clumps.csv");
  CHECK(CountLines(dir.str("out/final_clumps.csv")) == 1 + 20 + inserted);
  CHECK(CountLines(dir.str("out/final_particles.csv")) == 1 + 2 * (20 + inserted));  // members
}
