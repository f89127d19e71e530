// The CLI front of `demcal simulate`: its arguments reach SimulateOptions, bad ones are refused
// naming the option, and a scene that cannot be read exits 2.
#include "apps/simulate_command.h"

#include <catch2/catch.hpp>
#include <string>
#include <utility>
#include <vector>

#include "apps/command_line.h"
#include "core/io/scratch_dir.h"

using demcal::apps::AddSimulateCommand;
using demcal::apps::Command;
using demcal::testing::CheckHelpShows;
using demcal::testing::CheckInputRefused;
using demcal::testing::CheckRefused;
using demcal::testing::ScratchDir;

TEST_CASE("the simulate subcommand registers its arguments with the CLI", "[unit]") {
  CLI::App app{"test"};
  const Command simulate = AddSimulateCommand(app);
  REQUIRE(simulate.app != nullptr);
  CHECK(simulate.app->get_name() == "simulate");
  app.parse("simulate s.json --out o --threads 2 --quiet", /*program_name_included=*/false);
  CHECK(simulate.app->parsed());
  CHECK(simulate.app->get_option("--threads")->as<int>() == 2);
  CHECK(simulate.app->get_option("--out")->as<std::string>() == "o");
  CHECK(simulate.app->get_option("scene")->as<std::string>() == "s.json");
}

TEST_CASE("the checkpoint options are registered with the CLI", "[unit]") {
  CLI::App app{"test"};
  const Command simulate = AddSimulateCommand(app);
  app.parse("simulate s.json --out o --checkpoint-every-s 0.5 --restart o/checkpoint.bin",
            /*program_name_included=*/false);
  CHECK(simulate.app->get_option("--checkpoint-every-s")->as<double>() == 0.5);
  CHECK(simulate.app->get_option("--restart")->as<std::string>() == "o/checkpoint.bin");
}

TEST_CASE("simulate --help lists its options and the exit codes", "[unit][cli]") {
  CheckHelpShows(AddSimulateCommand, "simulate",
                 {"scene", "--out", "--threads", "--checkpoint-every-s", "--restart", "--quiet",
                  "--progress-interval-s", "Exit codes: 0 ok, 2 invalid input"});
}

TEST_CASE("simulate requires the scene and --out", "[unit][cli]") {
  CheckRefused(AddSimulateCommand, {"simulate", "s.json"}, "--out is required");
  CheckRefused(AddSimulateCommand, {"simulate", "--out", "o"}, "scene is required");
}

TEST_CASE("simulate refuses out-of-range options, naming the option and its range", "[unit][cli]") {
  const std::vector<std::pair<std::string, std::string>> bad = {{"--threads", "-1"},
                                                                {"--threads", "4097"},
                                                                {"--checkpoint-every-s", "-1"},
                                                                {"--checkpoint-every-s", "nan"},
                                                                {"--progress-interval-s", "0"},
                                                                {"--progress-interval-s", "1e7"}};
  for (const auto& [option, value] : bad)
    CheckRefused(AddSimulateCommand, {"simulate", "s.json", "--out", "o", option, value}, option);
  CheckRefused(AddSimulateCommand,
               {"simulate", "s.json", "--out", "o", "--progress-interval-s", "0"}, "(0, 1e+06] s");
  CheckRefused(AddSimulateCommand,
               {"simulate", "s.json", "--out", "o", "--checkpoint-every-s", "-1"}, "[0, 1e+06] s");
}

TEST_CASE("simulate refuses an empty path instead of taking the default", "[unit][cli]") {
  const std::string empty = "an empty string is not allowed";
  CheckRefused(AddSimulateCommand, {"simulate", "s.json", "--out", "o", "--restart", ""},
               "--restart: " + empty);
  CheckRefused(AddSimulateCommand, {"simulate", "s.json", "--out", ""}, "--out: " + empty);
  CheckRefused(AddSimulateCommand, {"simulate", "", "--out", "o"}, empty);
}

TEST_CASE("simulate exits 2 on a scene it cannot read, naming the file", "[unit][cli]") {
  ScratchDir dir("simulate_cli");
  CheckInputRefused(AddSimulateCommand,
                    {"simulate", dir.str("no_such.json"), "--out", dir.str("o")}, "no_such.json");
}
