// The CLI front of `demcal simulate`: its arguments reach SimulateOptions.
#include "apps/simulate_command.h"

#include <catch2/catch.hpp>
#include <string>

using demcal::apps::AddSimulateCommand;
using demcal::apps::Command;

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
