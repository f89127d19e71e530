#pragma once
// What `demcal calibrate` leaves in its output directory (docs/calibration.md lists every file,
// key and column):
//   result.json            termination, per-target residuals, parameters with σ, correlation,
//                          sensitivity matrix, identifiability report, which measurement would
//                          help, fidelity, provenance
//   evaluations.csv        one row per candidate: parameters, per target mean/sem, status
//   calibrated_params.json "demcal-params/1": calibrated values with σ, covariance, provenance
//   calibrated_params.liggghts  the calibrated model as LIGGGHTS `fix property/global` lines
//   targets.svg, convergence.svg, profile_<parameter>.svg, parameter_plane.svg (two or more
//                          parameters: the first two), calibration.svg (one parameter, one
//                          target: observable against the parameter)
// With a clump-count loop: clumps_<n>/ holds each count's files; clump_count.csv and
// clump_count.json the table n -> best match. (journal.jsonl is the evaluation journal's.)
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "calibrate/calibration.h"
#include "calibrate/target_evaluator.h"
#include "calibrate/target_gain.h"
#include "objectives/common/fidelity.h"
#include "workflow/calibration/study_file.h"

namespace demcal::workflow {

struct CalibrationRunInfo {
  const StudyFile* study = nullptr;
  objectives::Fidelity fidelity;  // of the first experiment (each experiment's is in result.json)
  int replicates = 0;
  uint64_t seed = 0;
  double wall_time_s = 0;
  int clump_count = 0;  // 0: the experiment files' shapes
  const calibrate::TargetEvaluator* evaluator = nullptr;
  std::vector<calibrate::TargetGain> gains;  // candidate targets, in the study's order
};

// result.json's "local_crossing": the line of calibrate/local_crossing.h with its crossing's value
// and σ in SI (null where not fitted). Stage results of `demcal reproduce` carry the same.
nlohmann::ordered_json LocalCrossingJson(const calibrate::LocalCrossing& line, double value,
                                         double sigma);

// Writes every file above into dir; false with the first error.
bool WriteCalibrationOutputs(const std::string& dir, const CalibrationRunInfo& info,
                             const calibrate::CalibrationSummary& summary, std::string* error);

}  // namespace demcal::workflow
