// Stage 1's shape calibration (paper section 2.4, Fig. 3) on a twin: the "measured" angle is
// demcal's own heap of 3-sphere EP clumps at Table 1's rolling friction (held), and the stage,
// judging counts 1 and 3 at that friction, must pick 3 or name the counts it cannot tell apart
// (3 among them). Its Fig. 3 table has a row per count with the angle, its noise and the cost,
// and the calibrated experiment copy carries the chosen shape.
#include <catch2/catch.hpp>
#include <fstream>

#include "core/io/scratch_dir.h"
#include "workflow/reproduce/species_twin.h"

namespace demcal::workflow {
namespace {

using testing_twin::RunStage;
using testing_twin::TwinWorkflow;
using testing_twin::WriteTable;

TEST_CASE("shape calibration twin: the count the data were made at, or the counts not told apart",
          "[dem][reproduce]") {
  testing::ScratchDir dir("clump_twin");
  // The twin's data: the heap of 3-sphere clumps (the angle it gives at the held friction).
  WriteTable(dir.str("made.csv"), 30.0, 1.0);
  const nlohmann::json made = RunStage(TwinWorkflow(dir.str("made.csv"), {3}), dir.str("made"));
  const nlohmann::json& made_row = made["species"]["EP"]["clump_table"][0];
  REQUIRE(made_row["angle_deg"].is_number());
  const double truth = made_row["angle_deg"].get<double>();

  WriteTable(dir.str("twin.csv"), truth, 1.0);
  const nlohmann::json r = RunStage(TwinWorkflow(dir.str("twin.csv"), {1, 3}), dir.str("twin"));
  const nlohmann::json& ep = r["species"]["EP"];
  REQUIRE(ep["clump_table"].size() == 2);
  for (const nlohmann::json& row : ep["clump_table"]) {
    CHECK(row["angle_deg"].is_number());
    CHECK(row["angle_sem_deg"].is_number());
    CHECK(row["cost"].is_number());
  }
  // Count 3 reproduces its own angle (common random numbers: the same seeds made the data).
  CHECK(ep["clump_table"][1]["within_noise"].get<bool>());
  const int chosen = ep["clump_count"].get<int>();
  const std::string note = ep["clump_note"].get<std::string>();
  INFO(note << "; angles " << ep["clump_table"][0]["angle_deg"] << " (n = 1), " << truth
            << " (n = 3)");
  if (chosen != 3) {  // a smaller count may only be chosen when the data cannot exclude it
    CHECK(chosen == 1);
    CHECK(note.find("not told apart") != std::string::npos);
  }
  // The calibrated copy for the later stages carries the chosen grain.
  nlohmann::json copy;
  std::ifstream(ep["calibrated_experiment"].get<std::string>()) >> copy;
  if (chosen == 3) CHECK(copy["species"][0]["clump"]["ellipsoid"]["sphere_count"] == 3);
  else CHECK_FALSE(copy["species"][0].contains("clump"));
}

}  // namespace
}  // namespace demcal::workflow
