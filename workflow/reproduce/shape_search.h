#pragma once
// Stage 1's shape calibration with the aspect ratio calibrated (paper section 2.4, Fig. 3; the
// paper fits its clumps to X-ray tomograms but gives no aspect ratios, so demcal calibrates one).
// For a species with "aspect_ratio" (workflow_file.h): the clump counts in ascending order; count
// 1 (a sphere, which has no aspect ratio) is one candidate at the held property; at each count
// n >= 2 the aspect ratio a of the prolate spheroid [a, 1, 1] is calibrated against the measured
// angle by the bracket optimiser (at most aspect_ratio.max_evaluations candidates), the property
// (Table 1's rolling friction) held at `start` throughout. Each count's range is the workflow's
// cut to the chains that are grains (aspect_bounds.h): from the shortest chain whose spheres stand
// apart (DistinctAspectLimit) to the longest whose spheres still touch (ConnectedAspectLimit).
// The first count whose calibrated shape matches the angle within noise is kept and the larger
// counts are not run: the smallest count that matches, at a bounded cost. A count matches when
// one candidate does, or, when the candidates bracket the measurement but each scatters more
// than it, when a straight line through those around the crossing meets the measurement as
// precisely as it is known (calibrate/local_crossing.h): the shape kept is then the crossing.
//
// Each count is one calibration (calibration_step.h) in <dir>/clumps_<n>/ with its own journal
// (a rerun resumes it), run on a copy of the species' experiment file with the property held and
// the n-sphere chain at the start aspect ratio (clumps_<n>/experiment.json).
//
//   ShapeSearch search;
//   if (!RunShapeSearch(ctx, k, ctx.StageDir("species") + "/BP", &search, &error)) ...;
//   search.chosen;  // the count kept (0: none matched; `nearest` is the least-cost row)
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "workflow/reproduce/aspect_bounds.h"
#include "workflow/reproduce/calibration_step.h"
#include "workflow/reproduce/reproduce_context.h"

namespace demcal::workflow {

// One count of the paper's Fig. 3 with its calibrated shape.
struct ShapeSearchRow {
  int count = 0;
  double aspect_ratio = 1;     // calibrated (1 for a sphere), dimensionless
  double aspect_sigma = 0;     // its standard error (NaN: not determined)
  double aspect_min = 0;       // the count's lower bound (DistinctAspectLimit)
  double aspect_max = 0;       // the count's upper bound (ConnectedAspectLimit)
  bool aspect_at_bound = false;  // the best candidate sits on a bound of the count's range
  double angle_deg = 0, angle_sem_deg = 0;  // the best candidate's heap angle ± standard error
  double measured_deg = 0, uncertainty_deg = 0;  // the species' measured angle ± u
  double cost = 0;             // ((angle − measured) / uncertainty)², dimensionless
  bool within_noise = false;
  // No candidate matched; the row is the line through the candidates around the crossing
  // (calibrate/local_crossing.h): aspect ratio and σ its crossing, the angle its value there
  // with its standard error; within_noise when that is no coarser than the measurement.
  bool local_fit = false;
  std::string termination, message;
  int heaps = 0;               // heap simulations run or reused from the journal
  double wall_time_s = 0;      // of the count's calibration in this run
  std::string result_dir;      // the count's calibration outputs
};

struct ShapeSearch {
  std::vector<ShapeSearchRow> rows;  // the counts run, ascending
  std::vector<int> not_run;          // counts after the one kept
  int chosen = 0;                    // the smallest count that matched (0: none)
  int nearest = -1;                  // index of the row used when none matched (least cost)
  std::string note;                  // the verdict in words
  const ShapeSearchRow* Used() const;  // the chosen row, else the nearest; null without rows
  // {"rows": [...], "note"} with the keys of clump_table.h's rows plus "aspect_ratio",
  // "aspect_ratio_sigma", "aspect_at_bound", "aspect_ratio_min", "aspect_ratio_max", "heaps",
  // "wall_time_s".
  nlohmann::json TableJson() const;
};

// The calibration of species k at `count` on `experiment_file` (the aspect ratio for count >= 2,
// the held property for count 1), in `dir`. The whole-workflow check parses it too.
CalibrationStep ShapeStep(const WorkflowFile& w, size_t k, int count,
                          const std::string& experiment_file, const std::string& dir);

// The Fig. 3 row of species s at `count` from its calibration's outcome: the best candidate's
// shape and angle, or, where no candidate matched and a line through those around the crossing
// was fitted, the line's crossing (local_fit).
ShapeSearchRow ShapeRowOf(const WorkflowSpecies& s, int count, const CalibrationOutcome& o);

bool RunShapeSearch(const ReproduceContext& ctx, size_t k, const std::string& dir,
                    ShapeSearch* out, std::string* error);

// Stage 1 for species k with a calibrated aspect ratio (stage_species_shape.cc): the search, the
// species' entry of the stage result (the Fig. 3 table, the grain kept, its calibrated experiment
// copy for the later stages) into *species and its summary values (angle, clump count, aspect
// ratio) into *values.
bool RunShapeSpecies(const ReproduceContext& ctx, size_t k, nlohmann::json* species,
                     nlohmann::json* values, std::string* error);

}  // namespace demcal::workflow
