// Golden-output regression tests (tests/golden/README.md): one small run per experiment and one
// plain `demcal simulate` scene, each run with 1 and 2 threads, their key outputs compared
// exactly with tests/golden/<case>/expected.txt. A run is bit-identical for a given input and
// seed whatever the thread count, so any difference is a change of the physics, of what a run
// measures, or of what it writes; if the change is intended, regenerate with
// DEMCAL_UPDATE_GOLDEN=1 and commit the new expected.txt with it.
#include <catch2/catch.hpp>
#include <set>
#include <sstream>
#include <string>

#include "core/io/scratch_dir.h"
#include "experiments/common/run_experiment.h"
#include "golden/golden_file.h"
#include "outputs/exit_codes.h"
#include "workflow/simulation/simulate.h"
#include "workflow/test_paths.h"

using namespace demcal::testing;
using namespace demcal::workflow;

namespace {

// What a run writes that is not a result: timings, the version, paths, the thread count (the
// one setting that must not matter) and the input's own description.
const std::set<std::string> kNotResults = {"wall_time_s",
                                           "phase_wall_time_s",
                                           "setup_wall_time_s",
                                           "total_wall_time_s",
                                           "demcal_version",
                                           "params_file",
                                           "scene",
                                           "threads",
                                           "threads_requested",
                                           "description",
                                           "scene_description"};

std::string CaseFile(const std::string& golden_case, const std::string& name) {
  return (RepoRoot() / "tests" / "golden" / golden_case / name).string();
}

// `demcal simulate tests/golden/simulate/scene.json`: summary.json and every cell of the final
// tables and of mass_flow.csv.
GoldenValues RunSimulateCase(int threads) {
  ScratchDir dir("golden_simulate");
  SimulateOptions o;
  o.scene_path = CaseFile("simulate", "scene.json");
  o.out_dir = dir.str("out");
  o.threads = threads;
  o.quiet = true;
  std::ostringstream log;
  const int code = RunSimulate(o, log);
  INFO(log.str());
  REQUIRE(code == kExitOk);
  GoldenValues got;
  AddJson(ReadOrderedJson(dir.str("out/summary.json")), "summary", kNotResults, &got);
  AddCsv(dir.str("out/final_particles.csv"), "final_particles", &got);
  AddCsv(dir.str("out/final_clumps.csv"), "final_clumps", &got);
  AddCsv(dir.str("out/mass_flow.csv"), "mass_flow", &got);
  return got;
}

// `demcal experiment KIND tests/golden/KIND/experiment.json --quick` (one replicate, so the
// threads go into the simulation): result.json, and the digest of the final state's VTK file
// (binary doubles: every particle's position to the last bit).
GoldenValues RunExperimentCase(const std::string& kind, const std::string& vtk_stem, int threads) {
  ScratchDir dir("golden_" + kind);
  ExperimentOptions o;
  o.kind = kind;
  o.params_path = CaseFile(kind, "experiment.json");
  o.out_dir = dir.str("out");
  o.quick = true;
  o.threads = threads;
  o.quiet = true;
  std::ostringstream log;
  const int code = RunExperiment(o, log);
  INFO(log.str());
  REQUIRE(code == kExitOk);
  GoldenValues got;
  AddJson(ReadOrderedJson(dir.str("out/result.json")), "result", kNotResults, &got);
  AddDigest(dir.str("out/" + vtk_stem + "_r0.vtk"), vtk_stem + "_r0.vtk", &got);
  return got;
}

}  // namespace

TEST_CASE("golden: simulate (a sticky pour of spheres and clumps past a post and a funnel)",
          "[golden][dem]") {
  for (int threads : {1, 2}) {
    INFO("threads: " << threads);
    CheckGolden("simulate", RunSimulateCase(threads));
  }
}

TEST_CASE("golden: experiment aor (a small slot heap of BP)", "[golden][dem]") {
  for (int threads : {1, 2}) {
    INFO("threads: " << threads);
    CheckGolden("aor", RunExperimentCase("aor", "heap", threads));
  }
}

TEST_CASE("golden: experiment discharge (1.5 g of BP through a small funnel)", "[golden][dem]") {
  for (int threads : {1, 2}) {
    INFO("threads: " << threads);
    CheckGolden("discharge", RunExperimentCase("discharge", "hopper", threads));
  }
}

TEST_CASE("golden: experiment segregation (a small ternary heap)", "[golden][dem]") {
  for (int threads : {1, 2}) {
    INFO("threads: " << threads);
    CheckGolden("segregation", RunExperimentCase("segregation", "heap", threads));
  }
}
