// The CLI front of `demcal cohesion`: the paper's defaults give a report (text or JSON), a value
// out of range or not a number exits 2 naming the option and the table's range.
#include "apps/cohesion_command.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "apps/command_line.h"
#include "calibrate/cohesion_scaling.h"
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

TEST_CASE("cohesion refuses a value out of range or not a number, naming the option and range",
          "[unit][cli]") {
  // The ranges are the input-limits table's, printed by Limit::Text as --help shows them.
  const std::vector<std::pair<std::string, std::string>> bad = {
      {"--poisson-ratio", "(-1, 0.5)"},        {"--radius-m", "(0, 1] m"},
      {"--gamma-J-m2", "(0, 100] J/m2"},       {"--youngs-sim-Pa", "(0, 1e+13] Pa"},
      {"--youngs-real-Pa", "(0, 1e+13] Pa"},   {"--density-kg-m3", "(0, 100000] kg/m3"},
      {"--gravity-m-s2", "(0, 1000] m/s2"},    {"--reference-gamma-J-m2", "(0, 100] J/m2"}};
  for (const auto& [option, range] : bad) {
    for (const char* value : {"-1", "nan", "1e999"})
      CheckRefused(AddCohesionCommand, {"cohesion", option, value},
                   option + ": '" + value + "' is not a number in " + range);
    CHECK(RunCli(AddCohesionCommand, {"cohesion", option, "-1"}).out.empty());  // no report
  }
  CheckRefused(AddCohesionCommand, {"cohesion", "--radius-m", "small"}, "--radius-m");
  CheckHelpShows(AddCohesionCommand, "cohesion", {"in (0, 100] J/m2", "in (-1, 0.5)"});
}

TEST_CASE("cohesion inputs out of range name the field with the table's bounds", "[unit]") {
  // The same check behind the options, for callers that fill CohesionInputs themselves.
  demcal::calibrate::CohesionInputs in;
  std::string error;
  CHECK(in.IsValid(&error));
  in.gamma_J_m2 = 101;
  CHECK_FALSE(in.IsValid(&error));
  CHECK(error == "gamma_J_m2 must be in (0, 100]");
  in = {};
  in.poisson_ratio = std::nan("");
  CHECK_FALSE(in.IsValid(&error));
  CHECK(error == "poisson_ratio must be in (-1, 0.5)");
}
