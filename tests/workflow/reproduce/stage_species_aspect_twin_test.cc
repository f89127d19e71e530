// Stage 1's shape calibration with the aspect ratio calibrated (shape_search.h) on a twin: the
// "measured" angle is demcal's own heap of 3-sphere EP clumps of aspect ratio 1.25 at Table 1's
// rolling friction (held), made through the fixed-shape path (the clump-count loop's chain). The
// search at 3 spheres starts at aspect ratio 2 with 1.25 as its lower bound and keeps the first
// candidate that matches the data within noise. Inside the bounds a DEM heap is chaotic in the
// shape (docs/reproduce.md), so which candidate matches first is a matter of noise: the test
// asks that the kept aspect ratio lies within two of its own standard deviations of the truth,
// and that the data determine it better than the search range does (a search that moved the
// wrong way, or re-chained another grain, fails one or the other). Its Fig. 3 row carries the
// calibrated aspect ratio, the angle, the cost and the heaps it took, and the calibrated
// experiment copy carries the grain kept.
#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>

#include "core/io/scratch_dir.h"
#include "workflow/reproduce/species_twin.h"

namespace demcal::workflow {
namespace {

using testing_twin::RunStage;
using testing_twin::TwinWorkflow;
using testing_twin::WriteTable;

constexpr double kTrueAspect = 1.25;

TEST_CASE("aspect-ratio twin: the aspect ratio the data were made at",
          "[dem][reproduce]") {
  testing::ScratchDir dir("aspect_twin");
  WriteTable(dir.str("made.csv"), 30.0, 1.0);
  WorkflowFile made_at = TwinWorkflow(dir.str("made.csv"), {3});
  made_at.species[0].semi_axes = {kTrueAspect, 1, 1};
  const nlohmann::json made = RunStage(made_at, dir.str("made"));
  REQUIRE(made["species"]["EP"]["clump_table"][0]["angle_deg"].is_number());
  const double truth = made["species"]["EP"]["clump_table"][0]["angle_deg"].get<double>();

  WriteTable(dir.str("twin.csv"), truth, 1.0);
  WorkflowFile w = TwinWorkflow(dir.str("twin.csv"), {3});
  w.species[0].semi_axes.clear();
  w.species[0].aspect_ratio = {.min = kTrueAspect, .max = 2.5, .start = 2.0,
                               .max_evaluations = 6, .enabled = true};
  const nlohmann::json r = RunStage(w, dir.str("twin"));
  const nlohmann::json& ep = r["species"]["EP"];
  REQUIRE(ep["clump_table"].size() == 1);
  const nlohmann::json& row = ep["clump_table"][0];
  INFO(ep["clump_note"] << "; truth " << truth << " deg at aspect ratio " << kTrueAspect
                        << "; row " << row.dump());
  CHECK(row["count"] == 3);
  CHECK(row["angle_sem_deg"].is_number());
  CHECK(row["cost"].is_number());
  CHECK(row["heaps"].get<int>() >= 2);  // at least one candidate's replicates
  // The bound of a count's cost: replicates × max_evaluations × the most replicate escalation
  // (calibrate::CalibrationOptions::max_replicate_factor, 4).
  CHECK(row["heaps"].get<int>() <= 2 * 6 * 4);
  // The data's own shape reproduces them (common random numbers), so a match exists in the bounds.
  REQUIRE(row["within_noise"].get<bool>());
  CHECK(ep["clump_count"] == 3);
  const double aspect = row["aspect_ratio"].get<double>();
  REQUIRE(row["aspect_ratio_sigma"].is_number());
  const double sigma = row["aspect_ratio_sigma"].get<double>();
  CHECK(std::abs(aspect - kTrueAspect) <= 2 * sigma);
  CHECK(sigma < 0.5 * (2.5 - kTrueAspect));
  // Within noise of the data (the calibration's criterion, |Δ| ≤ √(u² + sem²)).
  const double sem = row["angle_sem_deg"].get<double>();
  CHECK(std::abs(row["angle_deg"].get<double>() - truth) <= std::sqrt(1.0 + sem * sem));
  CHECK(r["values"]["aspect_ratio_EP"]["mean"] == aspect);
  // The calibrated copy for the later stages carries the grain kept.
  nlohmann::json copy;
  std::ifstream(ep["calibrated_experiment"].get<std::string>()) >> copy;
  const nlohmann::json& clump = copy["species"][0]["clump"]["ellipsoid"];
  CHECK(clump["sphere_count"] == 3);
  CHECK(clump["semi_axes"][0].get<double>() == aspect);
}

}  // namespace
}  // namespace demcal::workflow
