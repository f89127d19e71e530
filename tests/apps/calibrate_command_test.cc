// The CLI front of `demcal calibrate`: required arguments, refused budgets and thread counts
// naming the option, exit 2 for a missing study or an --out another run holds.
#include "apps/calibrate_command.h"

#include <catch2/catch.hpp>
#include <string>

#include "apps/command_line.h"
#include "core/io/scratch_dir.h"
#include "outputs/output_lock.h"
#include "workflow/test_paths.h"

using demcal::apps::AddCalibrateCommand;
using demcal::testing::CheckHelpShows;
using demcal::testing::CheckInputRefused;
using demcal::testing::CheckRefused;
using demcal::testing::ScratchDir;
using namespace demcal::workflow;

TEST_CASE("calibrate --help lists its options", "[unit][cli]") {
  CheckHelpShows(
      AddCalibrateCommand, "calibrate",
      {"study", "--out", "resume", "--quick", "--max-evaluations", "--threads", "--quiet"});
}

TEST_CASE("calibrate requires the study and --out", "[unit][cli]") {
  CheckRefused(AddCalibrateCommand, {"calibrate", "s.json"}, "--out is required");
  CheckRefused(AddCalibrateCommand, {"calibrate", "--out", "o"}, "study is required");
}

TEST_CASE("calibrate refuses an out-of-range budget or thread count, naming the option",
          "[unit][cli]") {
  for (const char* budget : {"0", "100001", "-3", "many"})
    CheckRefused(AddCalibrateCommand,
                 {"calibrate", "s.json", "--out", "o", "--max-evaluations", budget},
                 "--max-evaluations");
  for (const char* threads : {"-1", "1025"})
    CheckRefused(AddCalibrateCommand, {"calibrate", "s.json", "--out", "o", "--threads", threads},
                 "--threads");
}

TEST_CASE("calibrate refuses an empty study or --out", "[unit][cli]") {
  CheckRefused(AddCalibrateCommand, {"calibrate", "s.json", "--out", ""},
               "--out: an empty string is not allowed");
  CheckRefused(AddCalibrateCommand, {"calibrate", "", "--out", "o"}, "an empty string");
}

TEST_CASE("calibrate exits 2 on a missing study or an --out in use", "[unit][cli]") {
  ScratchDir dir("calibrate_cli");
  CheckInputRefused(AddCalibrateCommand,
                    {"calibrate", dir.str("no_such.json"), "--out", dir.str("o")}, "no_such.json");
  // A valid study whose --out another run holds: refused before anything runs.
  OutputLock held;
  std::string error;
  REQUIRE(LockOutputDirectory(dir.str("busy"), "test", &held, &error));
  const std::string study =
      (demcal::testing::RepoRoot() / "examples/calibrate_bp_rolling.json").string();
  CheckInputRefused(
      AddCalibrateCommand, {"calibrate", study, "--out", dir.str("busy")},
      "--out: output directory '" + dir.str("busy") + "' is in use by another demcal process");
}
