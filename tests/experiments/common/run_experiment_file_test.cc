// The typed front door of the experiments (run_experiment.h): a parsed file in, a result out.
// What it refuses, it refuses before running anything and says why in the result; the context
// it derives from a file is the file's own settings.
#include "experiments/common/run_experiment.h"

#include <catch2/catch.hpp>
#include <filesystem>
#include <sstream>

#include "experiments/aor/aor_runner.h"
#include "experiments/discharge/discharge_runner.h"
#include "outputs/exit_codes.h"
#include "workflow/test_paths.h"
#include "workflow/tiny_scene.h"

using namespace demcal::workflow;
using demcal::testing::RepoRoot;
using demcal::testing::ScratchDir;

namespace {

ExperimentFile AorExample() {
  ExperimentFile file;
  std::string error;
  REQUIRE(LoadExperimentFile((RepoRoot() / "examples/aor_bp.json").string(), &file, &error));
  return file;
}

}  // namespace

TEST_CASE("an experiment's context is the file's own settings", "[unit]") {
  const ExperimentFile file = AorExample();
  const ExperimentContext normal = ExperimentContextFor(file, "out", /*quick=*/false);
  const ExperimentContext quick = ExperimentContextFor(file, "out", /*quick=*/true);
  CHECK(normal.out_dir == "out");
  CHECK(normal.replicates == file.replicates);
  CHECK(normal.fidelity.name == file.fidelity.name);
  CHECK(quick.fidelity.name == "quick");
  CHECK(quick.fidelity.size_scale == file.quick_fidelity.size_scale);
}

TEST_CASE("the experiment front door refuses bad input before running anything", "[unit]") {
  ScratchDir dir("run_experiment_file");
  const std::string out = dir.str("out");
  std::ostringstream log;

  ExperimentFile unknown = AorExample();
  unknown.experiment = "no_such_experiment";
  ExperimentResult r = RunExperimentFile(unknown, ExperimentContextFor(unknown, out, true), log);
  CHECK(r.status == ExperimentStatus::kInvalidInput);
  CHECK(ExitCodeOf(r.status) == kExitInvalidInput);
  CHECK(r.message.find("unknown experiment 'no_such_experiment'") != std::string::npos);
  CHECK_FALSE(r.detail.has_value());

  ExperimentFile coarse = AorExample();
  ExperimentContext context = ExperimentContextFor(coarse, out, true);
  context.fidelity.size_scale = 0;  // outside [1, 20]
  r = RunExperimentFile(coarse, context, log);
  CHECK(r.status == ExperimentStatus::kInvalidInput);
  CHECK(r.message.rfind(coarse.source + ": ", 0) == 0);
  CHECK_FALSE(std::filesystem::exists(out));  // refused before the folder was made

  ExperimentFile bad_section = AorExample();
  bad_section.section["no_such_key"] = 1;
  r = RunExperimentFile(bad_section, ExperimentContextFor(bad_section, out, true), log);
  CHECK(r.status == ExperimentStatus::kInvalidInput);
  CHECK(r.message.find("the 'aor' section was refused") != std::string::npos);
  CHECK(log.str().find("no_such_key") != std::string::npos);  // the runner said which field
  CHECK_FALSE(std::filesystem::exists(dir.str("out/result.json")));
  REQUIRE(r.Detail<AorResult>() != nullptr);
  CHECK(r.Detail<AorResult>()->runs.empty());
  CHECK(r.Detail<DischargeResult>() == nullptr);  // the detail is the experiment's own type
}
