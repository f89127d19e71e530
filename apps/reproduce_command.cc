#include "apps/reproduce_command.h"

#include <iostream>
#include <memory>

#include "apps/cli_checks.h"
#include "workflow/reproduce/run_reproduce.h"

namespace demcal::apps {

namespace limits = objectives::limits;

using namespace demcal::workflow;

Command AddReproduceCommand(CLI::App& parent) {
  auto options = std::make_shared<ReproduceOptions>();
  CLI::App* app = parent.add_subcommand(
      "reproduce", "Run a paper's method end to end (demcal-workflow/1 file; bundled: alizadeh2018)");
  app->add_option("workflow", options->workflow,
                  "a bundled workflow name (datasets/NAME/workflow.json) or a workflow file")
      ->required()
      ->check(NonEmpty());
  app->add_option("--out", options->out_dir,
                  "output directory; holds the stage journal: run again with the same --out to resume")
      ->required()
      ->check(NonEmpty());
  app->add_flag("--quick", options->quick, "run every experiment at its quick fidelity");
  app->add_option("--threads", options->threads,
                  "runs side by side on this many cores (0: all; under mpirun: per rank, 0: 1)")
      ->check(CliRange<int>(limits::kThreads));
  app->add_flag("--quiet", options->quiet, "fewer progress lines on stderr");
  app->add_option("--bracket-points", options->bracket_points,
                  "candidates per round of the calibrations' bracket search (1: one at a time; "
                  "more fill more ranks, for more runs in all; resume with the same value)")
      ->check(CliRange<int>(limits::kBatchSize));
  app->add_flag("--calibrations-in-sequence", options->calibrations_in_sequence,
                "run stage 1's and 3's calibrations one after another instead of together "
                "(same results)");
  return {app, [options] { return RunReproduce(*options, std::cerr); }};
}

}  // namespace demcal::apps
