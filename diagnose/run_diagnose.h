#pragma once
// `demcal diagnose STUDY.json --out DIR [--quick] [--significance A] [--discrepancy-floor F]
//  [--effects K1,K2] [--species NAME] [--refits N] [--max-effects N] [--max-evaluations N]
//  [--threads N] [--quiet]`: the discrepancy workflow (docs/diagnose.md) on a calibration
// study (demcal-study/2): calibrate the base model, test for a gap, rank the library's candidate
// effects, add the winner and repeat while a significant gap remains. Progress on stderr;
// journals in DIR/journal/ (run again with the same --out to resume); outputs as in
// diagnose/report/diagnosis_outputs.h. Exit codes: 0 a verdict was reached (no missing effect,
// effect found, or gap remains/unexplained: diagnosis.json says which), 2 bad input, 3 the base
// calibration gave no value, 4 outputs could not be written.
#include <ostream>
#include <string>
#include <vector>

#include "diagnose/loop/diagnosis.h"

namespace demcal::diagnose {

struct DiagnoseCommandOptions {
  std::string study_path, out_dir;
  bool quick = false;
  DiagnoseOptions diagnose;
  std::vector<std::string> effects;  // empty: the whole library
  std::string species;               // empty: from the study's first parameter
  int max_evaluations = 0;           // base calibration budget (0: the study's)
  int threads = 0;
  bool quiet = false;
};

int RunDiagnose(const DiagnoseCommandOptions& options, std::ostream& log);

}  // namespace demcal::diagnose
