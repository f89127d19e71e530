#pragma once
// What `demcal calibrate` leaves in its output directory (README "Calibration" and
// docs/calibration.md list every file and column):
//   result.json            termination, best candidate, uncertainty, measurement, fidelity, provenance
//   evaluations.csv        one row per candidate (parameters, mean, sem, replicates, status)
//   calibrated_params.json "demcal-params/1": the calibrated pair properties as "interactions.pairs"
//                          entries, with provenance (dataset, fidelity, seeds, optimiser, σ)
//   calibrated_params.liggghts  the calibrated model's materials and pair table as LIGGGHTS
//                          `fix property/global` lines (calibrate/liggghts_export.h)
//   calibration.svg        the observable against the parameter (one parameter), target band
// (journal.jsonl is written by the evaluation journal itself.)
#include <string>

#include "workflow/files/study_file.h"
#include "calibrate/calibration.h"
#include "objectives/common/fidelity.h"

namespace demcal::workflow {

struct CalibrationRunInfo {
  const StudyFile* study = nullptr;
  objectives::Fidelity fidelity;
  int replicates = 0;
  uint64_t seed = 0;
  double wall_time_s = 0;
};

// Writes the five files into dir; false with the first error.
bool WriteCalibrationOutputs(const std::string& dir, const CalibrationRunInfo& info,
                             const calibrate::CalibrationSummary& summary, std::string* error);

}  // namespace demcal::workflow
