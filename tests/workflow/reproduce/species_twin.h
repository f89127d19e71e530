#pragma once
// Test helper for stage 1's shape-calibration twins: a one-species (EP) workflow at Table 1's
// rolling friction (held), a one-row measurement table holding the twin's "measured" angle, and
// the species stage run at quick fidelity.
#include <catch2/catch.hpp>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "workflow/reproduce/reproduce_context.h"
#include "workflow/reproduce/stages.h"
#include "workflow/test_paths.h"

namespace demcal::workflow::testing_twin {

inline WorkflowFile TwinWorkflow(const std::string& table, std::vector<int> counts) {
  WorkflowFile w;
  w.name = "twin";
  w.shape_assumption = "EP: n spheres on the long axis of a prolate spheroid";
  w.measurements = table;
  w.angle_uncertainty_deg = 1.0;
  w.angle_uncertainty_note = "twin";
  w.replicates = 2;
  WorkflowSpecies ep;
  ep.name = "EP";
  ep.experiment_file = (testing::RepoRoot() / "examples/aor_ep.json").string();
  ep.min = 0, ep.max = 1, ep.start = 0.05;  // Table 1's EP rolling friction, held
  ep.hold = true;
  ep.clump_counts = std::move(counts);
  ep.semi_axes = {2, 1, 1};
  w.species = {ep};
  return w;
}

inline void WriteTable(const std::string& path, double angle_deg, double u_deg) {
  std::ofstream(path) << "observable,unit,material,coating_PEG_wt_pct,test,value,uncertainty,"
                         "repeats,provenance,source\n"
                      << "angle_deg,deg,EP,0,pseudo-2D heap," << angle_deg << "," << u_deg
                      << ",,synthetic,twin made by demcal with clumps\n";
}

inline nlohmann::json RunStage(const WorkflowFile& w, const std::string& out) {
  std::ostringstream log;
  ReproduceContext ctx{.workflow = &w, .out_dir = out, .quick = true, .quiet = true, .log = &log};
  nlohmann::json result;
  std::string error;
  const bool ok = RunSpeciesStage(ctx, &result, &error);
  INFO(log.str() << error);
  REQUIRE(ok);
  return result;
}

}  // namespace demcal::workflow::testing_twin
