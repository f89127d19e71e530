#include "workflow/experiments/run_experiment.h"

#include <filesystem>
#include <iostream>
#include <memory>

#include "workflow/exit_codes.h"
#include "workflow/files/experiment_file.h"
#include "workflow/experiments/experiment_registry.h"

namespace demcal::workflow {


int RunExperiment(const ExperimentOptions& options, std::ostream& log) {
  const ExperimentKind* kind = FindExperimentKind(options.kind);
  if (!kind) {
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
  return kind->run(file, context, log);
}

}  // namespace demcal::workflow
