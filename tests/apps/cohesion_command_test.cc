// The CLI front of `demcal cohesion`: the paper's defaults give a report (text or JSON), a value
// out of range or not a number exits 2 naming the quantity.
#include "apps/cohesion_command.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "apps/command_line.h"
#include "outputs/exit_codes.h"

using demcal::apps::AddCohesionCommand;
using demcal::testing::CheckHelpShows;
using demcal::testing::CheckInputRefused;
using demcal::testing::CheckRefused;
using demcal::testing::RunCli;
using namespace demcal::workflow;

TEST_CASE("cohesion --help lists its options", "[unit][cli]") {
  CheckHelpShows(
      AddCohesionCommand, "cohesion",
      {"--gamma-J-m2", "--youngs-real-Pa", "--youngs-sim-Pa", "--poisson-ratio", "--radius-m",
       "--density-kg-m3", "--gravity-m-s2", "--reference-gamma-J-m2", "--json"});
}

TEST_CASE("cohesion reports the Cohesion number as text or JSON", "[unit][cli]") {
  const auto text = RunCli(AddCohesionCommand, {"cohesion"});
  CHECK(text.exit_code == kExitOk);
  CHECK_THAT(text.out, Catch::Contains("Cohesion number Coh = "));
  const auto json = RunCli(AddCohesionCommand, {"cohesion", "--json", "--radius-m", "3e-4"});
  REQUIRE(json.exit_code == kExitOk);
  const nlohmann::json j = nlohmann::json::parse(json.out);
  CHECK(j["format"] == "demcal-cohesion/1");
}

TEST_CASE("cohesion exits 2 on a value out of range or not a number, naming it", "[unit][cli]") {
  // The quantities are checked after parsing, by CohesionInputs::IsValid, which names them.
  const std::vector<std::pair<std::string, std::string>> bad = {
      {"--poisson-ratio", "poisson_ratio"},
      {"--radius-m", "radius_m"},
      {"--gamma-J-m2", "gamma_J_m2"},
      {"--youngs-sim-Pa", "youngs_sim_Pa"},
      {"--density-kg-m3", "density_kg_m3"}};
  for (const auto& [option, named] : bad) {
    CheckInputRefused(AddCohesionCommand, {"cohesion", option, "-1"}, named);
    CHECK(RunCli(AddCohesionCommand, {"cohesion", option, "-1"}).out.empty());  // no report
  }
  CheckRefused(AddCohesionCommand, {"cohesion", "--radius-m", "small"}, "--radius-m");
}
