#pragma once
// Calibrate: tune the parameters of a ParameterSpace so that a replicated observable matches
// a measurement, with an optimiser from the registry; every evaluation is journalled (via the
// evaluator), reported through a progress callback, and kept in the summary, which also gives
// the calibrated value's uncertainty from the local sensitivity (one parameter):
//   σ_θ = sqrt(u_measured² + sem_simulated²) / |d observable / dθ|,
// the slope fitted through the evaluations nearest the best. With more parameters than
// measurements the match is a valley, not a point; the summary says so rather than pretend.
//
//   CalibrationSummary s = Calibrate(evaluator, space, measurement, options, progress);
//   std::cerr << s.BriefReport();
#include <functional>
#include <string>
#include <vector>

#include "calibrate/optimiser.h"
#include "calibrate/parameter_space.h"
#include "calibrate/replicated_evaluator.h"

namespace demcal::calibrate {

struct Measurement {
  std::string observable;   // e.g. "angle_deg"
  double value = 0;         // SI or the observable's unit
  double uncertainty = 1;   // one standard deviation of the measurement, > 0
  std::string source;       // provenance: dataset file and row, or paper/table/figure
};

struct CalibrationOptions {
  std::string optimiser = "bracket";
  OptimiserOptions optimiser_options;
};

// Called after every evaluation (the journal already holds it).
using CalibrationProgress =
    std::function<void(const Evaluation& evaluation, const TrialResult& trial, double elapsed_s)>;

struct CalibrationSummary {
  std::string termination = "failed";  // the optimiser's (optimiser.h), or "invalid"
  std::string message = "Calibrate was not called";
  std::vector<Evaluation> history;     // in the order evaluated
  int best = -1;                       // index into history, −1 if no candidate gave a value
  double best_residual = 0;            // (simulated − measured) / uncertainty at the best
  // One parameter: sensitivity d observable / dθ and σ_θ (0 when not identifiable).
  std::vector<double> sensitivity;
  std::vector<double> uncertainty;
  std::string uncertainty_note;        // how σ_θ was obtained, or why it is not given
  int replicates_run = 0;
  int replicates_reused = 0;           // found in the journal (resumed work)
  std::string journal_error;           // first failure to write the journal ("" if none)
  bool ok() const { return best >= 0 && termination == "within_noise"; }
  std::string BriefReport(const ParameterSpace& space, const Measurement& m) const;
};

CalibrationSummary Calibrate(ReplicatedEvaluator& evaluator, const ParameterSpace& space,
                             const Measurement& measurement, const CalibrationOptions& options,
                             const CalibrationProgress& progress = {});

}  // namespace demcal::calibrate
