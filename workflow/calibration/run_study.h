#pragma once
// `demcal calibrate STUDY.json --out DIR [--quick] [--max-evaluations N] [--threads N] [--quiet]`:
// runs a calibration study (study_file.h) with its journal in DIR/journal.jsonl, so an
// interrupted study run again with the same --out resumes where it stopped (finished replicate
// runs are read back, not repeated). Progress and an ETA on stderr; outputs as in
// calibration_outputs.h. Exit code 0 when the measurement was matched within noise, 3 when not
// (out of range, budget, failed runs; result.json says which), 2 for bad input, 4 for outputs.
#include <ostream>
#include <string>

namespace demcal::workflow {

struct CalibrateOptions {
  std::string study_path;
  std::string out_dir;
  bool quick = false;        // the experiment's quick fidelity
  int max_evaluations = 0;   // 0: the study's budget
  int threads = 0;           // replicates side by side (0: all cores)
  bool quiet = false;
};

int RunCalibrate(const CalibrateOptions& options, std::ostream& log);

}  // namespace demcal::workflow
