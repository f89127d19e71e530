#pragma once
// What a calibration study returns to its caller (CalibrateStudy, run_study.h): how it ended,
// the calibrated parameters with their σ, each target's measured and simulated value with their
// uncertainties and the measurement's provenance, the clump-count table when the study has that
// loop, and the optimiser's full summary (candidates, covariance, identifiability). result.json
// holds the same numbers; it is an output, not the way to read them.
//
//   CalibrationResult r = CalibrateStudy(study, settings, log);
//   if (r.status == CalibrationStatus::kMatched)
//     use(r.parameters[0].value, r.parameters[0].sigma);
#include <limits>
#include <string>
#include <vector>

#include "calibrate/calibration.h"
#include "workflow/calibration/clump_count_table.h"
#include "workflow/calibration/study_file.h"

namespace demcal::workflow {

enum class CalibrationStatus {
  kMatched,            // the measurements were matched within noise
  kNotMatched,         // they were not (out of range, budget, failed runs: see termination)
  kInvalidInput,       // the study was refused (nothing, or nothing more, ran)
  kOutputUnavailable,  // the output folder could not be created or is in use; nothing ran
  kOutputError,        // an output file could not be written
};

// The process exit code of `demcal calibrate` for a status (outputs/exit_codes.h).
int ExitCodeOf(CalibrationStatus status);

inline constexpr double kNoValue = std::numeric_limits<double>::quiet_NaN();

struct CalibratedParameter {
  std::string name;
  std::string property;                 // the pair property's key ("sliding_friction", ...)
  std::string material_a, material_b;
  double value = kNoValue;              // SI, at the best candidate (NaN: no candidate)
  double sigma = kNoValue;              // SI (NaN: not determined)
  bool identifiable = false;
};

struct CalibratedTarget {
  std::string name, observable;
  double measured = 0, uncertainty = 0;  // the measurement and its standard uncertainty
  double simulated = 0, sem = 0;         // the best candidate's mean and its standard error
  double standardised_residual = 0;
  bool within_noise = false;
  std::string provenance;                // of the measurement: measured, inferred, synthetic
};

struct CalibrationResult {
  CalibrationStatus status = CalibrationStatus::kInvalidInput;
  calibrate::Termination termination = calibrate::Termination::kInvalid;
  std::string message;
  std::vector<CalibratedParameter> parameters;  // in the study's order
  std::vector<CalibratedTarget> targets;        // in the study's order
  // With a clump-count loop: the count chosen (0: none matched), one row per count tried, and
  // the fields above and below are of the chosen count's calibration (the largest count's when
  // none matched).
  int clump_count = 0;
  std::vector<ClumpCountRow> clump_counts;
  std::string out_dir;  // where this calibration's files are (the count's clumps_<n>/ in a loop)
  calibrate::CalibrationSummary summary;
};

// The parameters and targets of a summary of `study`'s calibration; status, out_dir and the
// clump fields left for the caller.
CalibrationResult CalibrationResultOf(const StudyFile& study,
                                      const calibrate::CalibrationSummary& summary);

}  // namespace demcal::workflow
