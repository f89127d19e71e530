// `demcal simulate --checkpoint-every-s / --restart`: a run split by a restart ends exactly where
// the uninterrupted run ends, its snapshot series continues, and checkpoints that do not fit the
// scene are refused.
#include <catch2/catch.hpp>
#include <filesystem>
#include <sstream>

#include "outputs/exit_codes.h"
#include "workflow/simulation/simulate.h"
#include "workflow/tiny_scene.h"

using namespace demcal::workflow;
using demcal::testing::ReadFile;
using demcal::testing::ReadJson;
using demcal::testing::ScratchDir;
using demcal::testing::TinyScene;
using demcal::testing::WriteScene;
using nlohmann::json;

namespace {

// The tiny scene with Δt = 1e-5 s: 2000 steps, snapshots every 500, and its first half (to
// 0.01 s) ends on a snapshot step.
json SplitScene(double duration_s) {
  json scene = TinyScene();
  scene["time"] = {{"duration_s", duration_s}, {"timestep_s", 1e-5}};
  return scene;
}

int Simulate(const std::string& scene, const std::string& out, double checkpoint_every_s,
             const std::string& restart = "", int threads = 1, std::string* log_text = nullptr) {
  SimulateOptions o;
  o.scene_path = scene;
  o.out_dir = out;
  o.threads = threads;
  o.quiet = true;
  o.checkpoint_every_s = checkpoint_every_s;
  o.restart_path = restart;
  std::ostringstream log;
  const int code = RunSimulate(o, log);
  if (log_text) *log_text = log.str();
  return code;
}

}  // namespace

TEST_CASE("a run split by a restart ends with the final state of the uninterrupted run",
          "[unit]") {
  ScratchDir dir("simulate_restart");
  const std::string full = WriteScene(dir, SplitScene(0.02), "full.json");
  const std::string half = WriteScene(dir, SplitScene(0.01), "half.json");

  REQUIRE(Simulate(full, dir.str("whole"), 0.01) == kExitOk);
  const json whole = ReadJson(dir.str("whole/summary.json"));
  CHECK(whole["outputs"]["checkpoint"] == "checkpoint.bin");
  CHECK(whole["outputs"]["checkpoint_time_s"].get<double>() == Approx(0.02));
  CHECK(whole["restarted_from"].is_null());
  CHECK(std::filesystem::exists(dir.str("whole/checkpoint.bin")));
  CHECK_FALSE(std::filesystem::exists(dir.str("whole/checkpoint.bin.tmp")));

  // First half, then the rest from its checkpoint into the same directory, on 2 threads.
  REQUIRE(Simulate(half, dir.str("split"), 0.004) == kExitOk);
  std::filesystem::copy_file(dir.str("split/checkpoint.bin"), dir.str("half.bin"));
  REQUIRE(Simulate(full, dir.str("split"), 0.004, dir.str("split/checkpoint.bin"), 2) == kExitOk);
  const json split = ReadJson(dir.str("split/summary.json"));
  CHECK(split["termination"] == "ok");
  CHECK(split["steps"] == 2000);
  CHECK(split["simulated_time_s"] == whole["simulated_time_s"]);
  CHECK(split["restarted_from"]["steps"] == 1000);
  CHECK(split["restarted_from"]["time_s"].get<double>() == Approx(0.01));
  CHECK(split["restarted_from"]["checkpoint"] == dir.str("split/checkpoint.bin"));

  const std::string expected = ReadFile(dir.str("whole/final_particles.csv"));
  REQUIRE(expected.size() > 100);
  CHECK(ReadFile(dir.str("split/final_particles.csv")) == expected);
  // The snapshot series continued: same files at the same times as the uninterrupted run.
  CHECK(ReadJson(dir.str("split/vtk/particles.vtk.series")) ==
        ReadJson(dir.str("whole/vtk/particles.vtk.series")));
  CHECK(ReadFile(dir.str("split/vtk/particles_000004.vtk")) ==
        ReadFile(dir.str("whole/vtk/particles_000004.vtk")));

  // Restarted into a fresh directory: the series starts with the restored state.
  REQUIRE(Simulate(full, dir.str("fresh"), 0, dir.str("half.bin")) == kExitOk);
  const json series = ReadJson(dir.str("fresh/vtk/particles.vtk.series"));
  REQUIRE(series["files"].size() == 3);  // t = 0.01, 0.015, 0.02
  CHECK(series["files"][0]["name"] == "particles_000000.vtk");
  CHECK(series["files"][0]["time"] == split["restarted_from"]["time_s"]);
  CHECK(ReadFile(dir.str("fresh/final_particles.csv")) == expected);
  CHECK_FALSE(std::filesystem::exists(dir.str("fresh/checkpoint.bin")));  // none asked for
}

TEST_CASE("a checkpoint that does not fit the scene is refused with exit code 2", "[unit]") {
  ScratchDir dir("simulate_restart_bad");
  const std::string half = WriteScene(dir, SplitScene(0.01), "half.json");
  REQUIRE(Simulate(half, dir.str("first"), 0.01) == kExitOk);
  const std::string checkpoint = dir.str("first/checkpoint.bin");

  json other = SplitScene(0.02);
  other["seed"] = 4;
  std::string log;
  CHECK(Simulate(WriteScene(dir, other, "other.json"), dir.str("other"), 0, checkpoint, 1, &log) ==
        kExitInvalidInput);
  CHECK_THAT(log, Catch::Contains(checkpoint + ": checkpoint: written for another scene: seed differs"));
  const json s = ReadJson(dir.str("other/summary.json"));
  CHECK(s["termination"] == "invalid_scene");
  CHECK_THAT(s["message"].get<std::string>(), Catch::Contains("another scene"));
  CHECK_FALSE(std::filesystem::exists(dir.str("other/final_particles.csv")));

  CHECK(Simulate(half, dir.str("missing"), 0, dir.str("nothing.bin"), 1, &log) ==
        kExitInvalidInput);
  CHECK_THAT(log, Catch::Contains("nothing.bin: checkpoint: cannot read the file: No such file"));

  const std::string bytes = ReadFile(checkpoint);
  std::ofstream(dir.str("truncated.bin"), std::ios::binary) << bytes.substr(0, bytes.size() / 2);
  CHECK(Simulate(half, dir.str("truncated"), 0, dir.str("truncated.bin"), 1, &log) ==
        kExitInvalidInput);
  CHECK_THAT(log, Catch::Contains("truncated.bin: checkpoint: truncated: the header announces"));
}

TEST_CASE("checkpoint options are validated", "[unit]") {
  SimulateOptions o;
  o.scene_path = "a.json";
  o.out_dir = "out";
  o.checkpoint_every_s = -1;
  std::string error;
  CHECK_FALSE(o.IsValid(&error));
  CHECK_THAT(error, Catch::Contains("--checkpoint-every-s"));
}
