#pragma once
// Running a virtual experiment, at two levels:
//  - the typed front door, RunExperimentFile: a parsed experiment file and a context in, an
//    ExperimentResult out (experiment_result.h); the runner writes its files into
//    context.out_dir as outputs. What in-process callers use (reproduce, a compute farm).
//  - the command, RunExperiment: `demcal experiment aor|discharge|segregation PARAMS.json --out
//    DIR [--replicates R] [--quick]` reads the file, calls the front door and turns a refused
//    input into DIR/rejected.json; it returns an exit code (outputs/exit_codes.h).
// docs/experiments/<experiment>.md lists every output file.
//
//   ExperimentFile file;  // LoadExperimentFile, ParseExperimentJson, or built in memory
//   ExperimentContext context = ExperimentContextFor(file, "out/aor", /*quick=*/true);
//   ExperimentResult r = RunExperimentFile(file, context, std::cerr);
//   if (r.status == ExperimentStatus::kOk) std::cout << r.Value("angle_deg")->mean;
#include <ostream>
#include <string>

#include "experiments/common/experiment_file.h"
#include "experiments/common/experiment_result.h"
#include "experiments/common/experiment_runner.h"

namespace demcal::workflow {

// The file's own settings as a context: its replicates, and its fidelity (its quick one with
// `quick`); threads 0 (all cores), not quiet.
ExperimentContext ExperimentContextFor(const ExperimentFile& file, const std::string& out_dir,
                                       bool quick);

// Runs file.experiment's runner into context.out_dir, which it creates and locks for this
// process while it runs (an earlier attempt's rejected.json is removed: a fresh run). A refused
// input (unknown experiment, invalid fidelity, refused section) is logged as "error: ..." and
// returned as kInvalidInput with the reason in `message`; nothing is run then.
ExperimentResult RunExperimentFile(const ExperimentFile& file, const ExperimentContext& context,
                                   std::ostream& log);

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
