#include "apps/experiment_command.h"

#include <iostream>
#include <memory>

#include "apps/cli_checks.h"
#include "experiments/common/run_experiment.h"
#include "experiments/experiment_registry.h"

namespace demcal::apps {

using namespace demcal::workflow;

Command AddExperimentCommand(CLI::App& parent) {
  auto options = std::make_shared<ExperimentOptions>();
  std::string described;
  for (const std::string& name : ExperimentKindNames())
    described += (described.empty() ? "" : ", ") + std::string(FindExperimentKind(name)->description);
  CLI::App* app = parent.add_subcommand("experiment", "Run a virtual experiment (" + described + ")");
  app->add_option("kind", options->kind, JoinNames(ExperimentKindNames()))
      ->required()
      ->check(CLI::IsMember(ExperimentKindNames()));
  app->add_option("params", options->params_path, "experiment parameter file (demcal-experiment/1 JSON)")
      ->required()
      ->check(NonEmpty());
  app->add_option("--out", options->out_dir, "output directory (created if missing)")
      ->required()
      ->check(NonEmpty());
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
