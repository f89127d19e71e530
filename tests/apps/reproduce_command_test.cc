// The CLI front of `demcal reproduce`: required arguments, a refused thread count naming the
// option, exit 2 for a workflow that is neither a bundled name nor a file.
#include "apps/reproduce_command.h"

#include <catch2/catch.hpp>
#include <string>
#include <vector>

#include "apps/command_line.h"
#include "core/io/scratch_dir.h"

using demcal::apps::AddReproduceCommand;
using demcal::testing::CheckHelpShows;
using demcal::testing::CheckInputRefused;
using demcal::testing::CheckRefused;
using demcal::testing::ScratchDir;

TEST_CASE("reproduce --help lists its options and the bundled workflow", "[unit][cli]") {
  CheckHelpShows(AddReproduceCommand, "reproduce",
                 {"workflow", "alizadeh2018", "--out", "--quick", "--threads", "--quiet",
                  "--bracket-points", "--calibrations-in-sequence"});
}

TEST_CASE("reproduce requires the workflow and --out", "[unit][cli]") {
  CheckRefused(AddReproduceCommand, {"reproduce", "alizadeh2018"}, "--out is required");
  CheckRefused(AddReproduceCommand, {"reproduce", "--out", "o"}, "workflow is required");
}

TEST_CASE("reproduce refuses an out-of-range thread count, naming the option", "[unit][cli]") {
  for (const char* threads : {"-1", "1025", "all"})
    CheckRefused(AddReproduceCommand,
                 {"reproduce", "alizadeh2018", "--out", "o", "--threads", threads}, "--threads");
}

TEST_CASE("reproduce refuses a bracket point count outside [1, 1024], naming the option",
          "[unit][cli]") {
  for (const char* k : {"0", "1025", "two"})
    CheckRefused(AddReproduceCommand,
                 {"reproduce", "alizadeh2018", "--out", "o", "--bracket-points", k},
                 "--bracket-points");
}

TEST_CASE("reproduce refuses an empty workflow or --out", "[unit][cli]") {
  CheckRefused(AddReproduceCommand, {"reproduce", "alizadeh2018", "--out", ""},
               "--out: an empty string is not allowed");
  CheckRefused(AddReproduceCommand, {"reproduce", "", "--out", "o"}, "an empty string");
}

TEST_CASE("reproduce exits 2 on an unknown workflow name, saying what a name is", "[unit][cli]") {
  ScratchDir dir("reproduce_cli");
  const std::vector<std::string> args = {"reproduce", "no_such_workflow", "--out", dir.str("o")};
  CheckInputRefused(AddReproduceCommand, args, "no_such_workflow");
  CheckInputRefused(AddReproduceCommand, args,
                    "a bundled workflow name is a folder datasets/NAME/");
}
