#pragma once
// One calibration of `demcal reproduce` (a species' friction, Γ at one coating level): built
// as a demcal-study/2 document, written into its own folder as the record of what ran, parsed
// into a StudyFile and run by the calibration layer's front door (CalibrateStudy,
// workflow/calibration/run_study.h) with that folder as its output, so its evaluation journal,
// result.json, calibrated_params.json/.liggghts and plots land there, and a rerun after a kill
// resumes inside it; the outcome comes from the returned CalibrationResult. One parameter, one
// angle target, the `bracket` optimiser (regula falsi that stops when the angle is matched
// within noise; docs/calibration.md).
//
//   CalibrationStep step{.dir = ctx.StageDir("species") + "/BP", ...};
//   CalibrationOutcome o;
//   if (!RunCalibrationStep(ctx, step, &o, &error)) ...;   // false only for bad input / outputs
#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "calibrate/local_crossing.h"
#include "calibrate/termination.h"
#include "workflow/reproduce/reproduce_context.h"

namespace demcal::workflow {

struct CalibrationStep {
  std::string dir;              // created if needed; holds study.json and every output
  std::string experiment_file;  // absolute or relative to the working directory
  std::string parameter, property, material_a, material_b;
  double min = 0, max = 1, start = 0.5;
  std::string table, material;  // the measurement row: table, material and conditions
  nlohmann::json conditions = nlohmann::json::object();
  double uncertainty = 1;       // used when the row has none
  std::string uncertainty_note;
  int replicates = 2;
  int max_evaluations = 12;
  std::vector<int> clump_counts;  // optional n loop of material_a's species
  std::vector<double> semi_axes;
};

struct CalibrationOutcome {
  int exit_code = 0;             // `demcal calibrate`'s: 0 matched, 3 not matched (see termination)
  calibrate::Termination termination = calibrate::Termination::kFailed;
  std::string message;
  double value = 0, sigma = 0;   // the calibrated parameter (sigma NaN: not determined)
  double measured = 0, uncertainty = 0, simulated = 0, sem = 0;
  std::string provenance;        // of the measurement row: measured, inferred, synthetic
  int clump_count = 0;           // chosen count (0: no loop)
  std::string result_dir;        // where result.json is (dir, or dir/clumps_<n>)
  // No candidate within noise: the line through the candidates around the crossing
  // (calibrate/local_crossing.h). Where it was fitted, value, sigma, simulated and sem above are
  // the line's (by_line): its crossing is the best estimate of where the measurement is met,
  // and it matches when the line is as precise as the measurement.
  calibrate::LocalCrossing local_crossing;
  bool by_line = false;
  bool Matched() const;  // a candidate within noise, or the line as precise as the measurement
  std::string MatchText() const;  // "", "by a line ...", or "not matched: <termination>: ..."
  nlohmann::json ToJson() const;
};

// Where no candidate matched and o->local_crossing was fitted: value and sigma become the
// crossing's (`value`, `sigma`, SI), simulated and sem the line's there, by_line set
// (RunCalibrationStep's outcomes have had this done).
void TakeLine(double value, double sigma, CalibrationOutcome* o);

bool RunCalibrationStep(const ReproduceContext& ctx, const CalibrationStep& step,
                        CalibrationOutcome* out, std::string* error);
// The step's study parsed as RunCalibrationStep would (nothing written, nothing run): false with
// the reason it would be refused, which names the study's own field.
bool CheckCalibrationStep(const CalibrationStep& step, std::string* error);

}  // namespace demcal::workflow
