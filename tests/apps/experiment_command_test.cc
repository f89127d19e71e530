// The CLI front of `demcal experiment`: its choices come from the experiment registry, bad
// arguments are refused naming the option, and a bad file exits 2 before anything runs.
#include "apps/experiment_command.h"

#include <catch2/catch.hpp>
#include <string>

#include "apps/command_line.h"
#include "core/io/scratch_dir.h"
#include "experiments/experiment_registry.h"
#include "workflow/test_paths.h"

using demcal::apps::AddExperimentCommand;
using demcal::testing::CheckHelpShows;
using demcal::testing::CheckInputRefused;
using demcal::testing::CheckRefused;
using demcal::testing::ScratchDir;
using namespace demcal::workflow;

TEST_CASE("experiment --help lists every experiment of the registry and the options",
          "[unit][cli]") {
  REQUIRE(ExperimentKindNames().size() >= 3);
  std::vector<std::string> words = {"--out", "--replicates", "--quick", "--threads", "--quiet"};
  for (const std::string& name : ExperimentKindNames()) {
    words.push_back(name);
    words.push_back(FindExperimentKind(name)->description);
  }
  CheckHelpShows(AddExperimentCommand, "experiment", words);
}

TEST_CASE("experiment refuses an unknown kind, listing the registry's", "[unit][cli]") {
  const std::vector<std::string> args = {"experiment", "heap", "p.json", "--out", "o"};
  CheckRefused(AddExperimentCommand, args, "heap");
  for (const std::string& name : ExperimentKindNames())
    CheckRefused(AddExperimentCommand, args, name);
}

TEST_CASE("experiment requires the kind, the file and --out", "[unit][cli]") {
  CheckRefused(AddExperimentCommand, {"experiment", "aor", "p.json"}, "--out is required");
  CheckRefused(AddExperimentCommand, {"experiment", "aor", "--out", "o"}, "params is required");
  CheckRefused(AddExperimentCommand, {"experiment", "--out", "o"}, "kind is required");
}

TEST_CASE("experiment refuses out-of-range replicates and threads, naming the option",
          "[unit][cli]") {
  for (const char* replicates : {"0", "1001", "two"})
    CheckRefused(AddExperimentCommand,
                 {"experiment", "aor", "p.json", "--out", "o", "--replicates", replicates},
                 "--replicates");
  for (const char* threads : {"-1", "1025"})
    CheckRefused(AddExperimentCommand,
                 {"experiment", "aor", "p.json", "--out", "o", "--threads", threads}, "--threads");
}

TEST_CASE("experiment refuses an empty file or --out", "[unit][cli]") {
  CheckRefused(AddExperimentCommand, {"experiment", "aor", "e.json", "--out", ""},
               "--out: an empty string is not allowed");
  CheckRefused(AddExperimentCommand, {"experiment", "aor", "", "--out", "o"}, "an empty string");
}

TEST_CASE("experiment exits 2 on a missing file or a file of another experiment", "[unit][cli]") {
  ScratchDir dir("experiment_cli");
  CheckInputRefused(AddExperimentCommand,
                    {"experiment", "aor", dir.str("no_such.json"), "--out", dir.str("o")},
                    "no_such.json");
  const std::string aor_file = (demcal::testing::RepoRoot() / "examples/aor_bp.json").string();
  CheckInputRefused(AddExperimentCommand,
                    {"experiment", "discharge", aor_file, "--out", dir.str("o"), "--quiet"},
                    "examples/aor_bp.json is an 'aor' experiment file, not 'discharge'; run it "
                    "with `demcal experiment aor`");
  const std::string discharge_file =
      (demcal::testing::RepoRoot() / "examples/discharge_bp.json").string();
  CheckInputRefused(AddExperimentCommand,
                    {"experiment", "aor", discharge_file, "--out", dir.str("o"), "--quiet"},
                    "discharge_bp.json is a 'discharge' experiment file, not 'aor'; run it with "
                    "`demcal experiment discharge`");
}
