#include "apps/experiment_command.h"

#include <iostream>
#include <memory>

#include "workflow/experiments/run_experiment.h"

namespace demcal::apps {

using namespace demcal::workflow;

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
