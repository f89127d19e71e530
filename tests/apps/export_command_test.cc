// The CLI front of `demcal export liggghts`: help, refused options, a refused law naming the
// pair (exit 2, nothing written), and a written deck (exit 0) with the files docs/export.md lists.
#include "apps/export_command.h"

#include <catch2/catch.hpp>
#include <filesystem>
#include <string>

#include "apps/command_line.h"
#include "outputs/exit_codes.h"
#include "tests/workflow/test_paths.h"
#include "core/io/scratch_dir.h"

using demcal::apps::AddExportCommand;
using demcal::testing::CheckHelpShows;
using demcal::testing::CheckInputRefused;
using demcal::testing::CheckRefused;
using demcal::testing::RunCli;
namespace fs = std::filesystem;

TEST_CASE("export --help lists its options", "[unit][cli]") {
  CheckHelpShows(AddExportCommand, "export",
                 {"liggghts", "--out", "--params", "--fidelity", "--rolling-conversion",
                  "--cohesion-approximation", "--dump-interval-s"});
}

TEST_CASE("export refuses unknown targets and option values", "[unit][cli]") {
  CheckRefused(AddExportCommand, {"export", "lammps", "x.json", "--out", "d"}, "target");
  CheckRefused(AddExportCommand,
               {"export", "liggghts", "x.json", "--out", "d", "--fidelity", "big"}, "--fidelity");
  CheckRefused(AddExportCommand, {"export", "liggghts", "x.json"}, "--out");
}

TEST_CASE("export liggghts: cdt refused by pair; with the torque option a deck is written",
          "[unit][cli]") {
  const demcal::testing::ScratchDir scratch("export_command_test");
  const fs::path dir = scratch.path() / "deck";
  const std::string aor = (demcal::testing::RepoRoot() / "examples/aor_bp.json").string();
  CheckInputRefused(AddExportCommand,
                    {"export", "liggghts", aor, "--out", dir.string(), "--fidelity", "quick"},
                    "material pair BP–BP");
  CHECK_FALSE(fs::exists(dir / "in.demcal"));
  const auto written =
      RunCli(AddExportCommand, {"export", "liggghts", aor, "--out", dir.string(), "--fidelity",
                                "quick", "--rolling-conversion", "torque"});
  CHECK(written.exit_code == demcal::workflow::kExitOk);
  for (const char* f : {"in.demcal", "particles.data", "export.json"}) CHECK(fs::exists(dir / f));
  CHECK(fs::is_directory(dir / "post"));
  fs::remove_all(dir);
}
