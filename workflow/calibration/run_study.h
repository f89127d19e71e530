#pragma once
// Running a calibration study, at two levels:
//  - the typed front door, CalibrateStudy: a parsed study (study_file.h: every experiment file
//    and measurement already read into it) and settings in, a CalibrationResult out
//    (calibration_result.h). The evaluation journal and every output (calibration_outputs.h)
//    go to settings.out_dir; an interrupted study run again into the same folder resumes
//    where it stopped (finished replicate runs are read back, not repeated).
//  - the command, RunCalibrate: `demcal calibrate STUDY.json --out DIR [--quick]
//    [--max-evaluations N] [--threads N] [--quiet]` reads the study and calls the front door.
//    Exit code 0 when the measurement was matched within noise, 3 when not (out of range,
//    budget, failed runs; result.json says which), 2 for bad input, 4 for outputs.
// Progress and an ETA on the log. Under mpirun every rank runs this with the same inputs and the
// replicate runs are farmed over the ranks (objectives/farm/farm.h); only rank 0 locks and writes
// --out, the others read the journal without writing it (docs/scale.md).
//
//   StudyFile study;  // LoadStudyFile, or ParseStudyJson of a document built in memory
//   CalibrationResult r = CalibrateStudy(study, {.out_dir = "out/bp", .quick = true}, std::cerr);
//   if (r.status == CalibrationStatus::kMatched)
//     std::cout << r.parameters[0].value << " ± " << r.parameters[0].sigma;
#include <ostream>
#include <string>

#include "workflow/calibration/calibration_result.h"
#include "workflow/calibration/study_file.h"

namespace demcal::workflow {

struct CalibrateSettings {
  std::string out_dir;       // created and locked for this process while the study runs
  bool quick = false;        // the experiments' quick fidelity
  int max_evaluations = 0;   // 0: the study's budget
  int threads = 0;           // replicates side by side (0: all cores; per rank under mpirun)
  bool quiet = false;        // no progress lines
  double run_time_limit_s = 0;  // under mpirun: copy a run to another rank after (0: auto)
};

CalibrationResult CalibrateStudy(const StudyFile& study, const CalibrateSettings& settings,
                                 std::ostream& log);

struct CalibrateOptions {
  std::string study_path;
  std::string out_dir;
  bool quick = false;        // the experiment's quick fidelity
  int max_evaluations = 0;   // 0: the study's budget
  int threads = 0;           // replicates side by side (0: all cores)
  bool quiet = false;
  double run_time_limit_s = 0;
};

int RunCalibrate(const CalibrateOptions& options, std::ostream& log);

}  // namespace demcal::workflow
