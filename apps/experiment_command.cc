#include "apps/experiment_command.h"

#include <filesystem>
#include <iostream>
#include <memory>

#include "apps/exit_codes.h"
#include "apps/experiment_file.h"
#include "apps/experiment_runner.h"

namespace demcal::apps {

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

Command AddExperimentCommand(CLI::App& parent) {
  auto options = std::make_shared<ExperimentOptions>();
  CLI::App* app = parent.add_subcommand(
      "experiment", "Run a virtual experiment (angle of repose, funnel discharge, segregation heap)");
  app->add_option("kind", options->kind, "aor, discharge or segregation")
      ->required()
      ->check(CLI::IsMember({"aor", "discharge", "segregation"}));
  app->add_option("params", options->params_path, "experiment parameter file (demcal-experiment/1 JSON)")
      ->required();
  app->add_option("--out", options->out_dir, "output directory (created if missing)")->required();
  app->add_option("--replicates", options->replicates,
                  "runs with different seeds (default: the file's 'replicates')")
      ->check(CLI::Range(1, 1000));
  app->add_flag("--quick", options->quick, "run at the file's quick fidelity (a fast preview)");
  app->add_option("--threads", options->threads,
                  "replicates run side by side on this many cores (0: all)")
      ->check(CLI::Range(0, 1024));
  app->add_flag("--quiet", options->quiet, "no progress lines on stderr");
  return {app, [options] { return RunExperiment(*options, std::cerr); }};
}

}  // namespace demcal::apps
