#pragma once
// `demcal experiment aor|discharge|segregation PARAMS.json --out DIR [--replicates R] [--quick]`
// runs a virtual experiment (objectives/) on a parameter file and writes DIR/result.json with
// its tables and pictures (docs/experiments.md lists every file).
#include <ostream>
#include <string>

namespace demcal::workflow {

struct ExperimentOptions {
  std::string kind;         // "aor", "discharge", "segregation"
  std::string params_path;
  std::string out_dir;
  int replicates = 0;       // 0: the file's "replicates"
  bool quick = false;       // run at the file's quick fidelity
  int threads = 0;          // 0: all cores
  bool quiet = false;
};

int RunExperiment(const ExperimentOptions& options, std::ostream& log);

}  // namespace demcal::workflow
