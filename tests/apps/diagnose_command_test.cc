// The CLI front of `demcal diagnose`: required arguments, each ranged option refused out of
// range naming itself, exit 2 for a missing study or an effect the library does not have.
#include "apps/diagnose_command.h"

#include <catch2/catch.hpp>
#include <string>
#include <utility>
#include <vector>

#include "apps/command_line.h"
#include "core/io/scratch_dir.h"
#include "workflow/test_paths.h"

using demcal::apps::AddDiagnoseCommand;
using demcal::testing::CheckHelpShows;
using demcal::testing::CheckInputRefused;
using demcal::testing::CheckRefused;
using demcal::testing::ScratchDir;

TEST_CASE("diagnose --help lists its options", "[unit][cli]") {
  CheckHelpShows(AddDiagnoseCommand, "diagnose",
                 {"study", "--out", "--quick", "--significance", "--discrepancy-floor", "--effects",
                  "--species", "--refits", "--max-effects", "--extra-refits", "--max-evaluations",
                  "--threads", "--quiet"});
}

TEST_CASE("diagnose requires the study and --out", "[unit][cli]") {
  CheckRefused(AddDiagnoseCommand, {"diagnose", "s.json"}, "--out is required");
  CheckRefused(AddDiagnoseCommand, {"diagnose", "--out", "o"}, "study is required");
}

TEST_CASE("diagnose refuses each ranged option out of range, naming it", "[unit][cli]") {
  const std::vector<std::pair<std::string, std::string>> bad = {
      {"--significance", "0"},       {"--significance", "0.6"}, {"--discrepancy-floor", "-1"},
      {"--discrepancy-floor", "11"}, {"--refits", "0"},         {"--refits", "11"},
      {"--max-effects", "0"},        {"--max-effects", "7"},    {"--extra-refits", "21"},
      {"--max-evaluations", "0"},    {"--threads", "-1"},       {"--refits", "two"}};
  for (const auto& [option, value] : bad)
    CheckRefused(AddDiagnoseCommand, {"diagnose", "s.json", "--out", "o", option, value}, option);
  // NaN passes a plain CLI::Range; the ranges printed are the limits table's, as --help shows.
  CheckRefused(AddDiagnoseCommand, {"diagnose", "s.json", "--out", "o", "--significance", "nan"},
               "--significance: 'nan' is not a number in (0, 0.5)");
  CheckRefused(AddDiagnoseCommand,
               {"diagnose", "s.json", "--out", "o", "--discrepancy-floor", "nan"},
               "--discrepancy-floor: 'nan' is not a number in [0, 10] single-run scatters");
  CheckRefused(AddDiagnoseCommand, {"diagnose", "s.json", "--out", "o", "--significance", "0.5"},
               "--significance: '0.5' is not a number in (0, 0.5)");
  CheckHelpShows(AddDiagnoseCommand, "diagnose",
                 {"in (0, 0.5)", "in [0, 10] single-run scatters"});
}

TEST_CASE("diagnose refuses an empty name or path instead of taking the default", "[unit][cli]") {
  const std::string empty = "an empty string is not allowed";
  CheckRefused(AddDiagnoseCommand, {"diagnose", "s.json", "--out", "o", "--species", ""},
               "--species: " + empty);
  CheckRefused(AddDiagnoseCommand, {"diagnose", "s.json", "--out", "o", "--effects", ""},
               "--effects: " + empty);
  CheckRefused(AddDiagnoseCommand, {"diagnose", "s.json", "--out", ""}, "--out: " + empty);
  CheckRefused(AddDiagnoseCommand, {"diagnose", "", "--out", "o"}, empty);
}

TEST_CASE("diagnose exits 2 on a missing study or an unknown effect", "[unit][cli]") {
  ScratchDir dir("diagnose_cli");
  CheckInputRefused(AddDiagnoseCommand,
                    {"diagnose", dir.str("no_such.json"), "--out", dir.str("o")}, "no_such.json");
  const std::string study =
      (demcal::testing::RepoRoot() / "examples/diagnose/diagnose_rolling_strong.json").string();
  CheckInputRefused(
      AddDiagnoseCommand,
      {"diagnose", study, "--out", dir.str("o"), "--effects", "rolling_resistance,telekinesis"},
      "--effects: unknown effect 'telekinesis'");
}
