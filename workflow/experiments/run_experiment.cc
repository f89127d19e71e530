#include "workflow/experiments/run_experiment.h"

#include <filesystem>
#include <iostream>
#include <memory>

#include "workflow/exit_codes.h"
#include "workflow/files/experiment_file.h"
#include "workflow/experiments/experiment_runner.h"

namespace demcal::workflow {

namespace {

struct NamedRunner {
  const char* name;
  ExperimentRunner run;
};

// Adding an experiment: one runner file and one line here.
constexpr NamedRunner kRunners[] = {
    {"aor", &RunAorExperiment},
    {"discharge", &RunDischargeExperiment},
    {"segregation", &RunSegregationExperiment},
};

ExperimentRunner FindRunner(const std::string& kind) {
  for (const NamedRunner& r : kRunners)
    if (kind == r.name) return r.run;
  return nullptr;
}

}  // namespace

int RunExperiment(const ExperimentOptions& options, std::ostream& log) {
  const ExperimentRunner runner = FindRunner(options.kind);
  if (!runner) {
    log << "error: unknown experiment '" << options.kind << "' (aor, discharge, segregation)\n";
    return kExitInvalidInput;
  }
  ExperimentFile file;
  std::string error;
  if (!LoadExperimentFile(options.params_path, &file, &error)) {
    log << "error: " << error << "\n";
    return kExitInvalidInput;
  }
  if (file.experiment != options.kind) {
    log << "error: " << options.params_path << ": field 'experiment' = '" << file.experiment
        << "' but the command asks for '" << options.kind << "'\n";
    return kExitInvalidInput;
  }
  ExperimentContext context;
  context.out_dir = options.out_dir;
  context.replicates = options.replicates > 0 ? options.replicates : file.replicates;
  context.fidelity = options.quick ? file.quick_fidelity : file.fidelity;
  context.threads = options.threads;
  context.quiet = options.quiet;
  if (!context.fidelity.IsValid(&error)) {
    log << "error: " << options.params_path << ": " << error << "\n";
    return kExitInvalidInput;
  }
  std::error_code ec;
  std::filesystem::create_directories(options.out_dir, ec);
  if (ec) {
    log << "error: --out: cannot create '" << options.out_dir << "': " << ec.message() << "\n";
    return kExitOutputError;
  }
  return runner(file, context, log);
}

}  // namespace demcal::workflow
