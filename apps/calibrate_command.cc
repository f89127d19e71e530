#include "apps/calibrate_command.h"

#include <iostream>
#include <memory>

#include "apps/cli_checks.h"
#include "workflow/calibration/run_study.h"

namespace demcal::apps {

namespace limits = objectives::limits;

using namespace demcal::workflow;

Command AddCalibrateCommand(CLI::App& parent) {
  auto options = std::make_shared<CalibrateOptions>();
  CLI::App* app = parent.add_subcommand(
      "calibrate", "Calibrate DEM parameters against measurements (demcal-study/2 file)");
  app->add_option("study", options->study_path,
                  "study file (demcal-study/2 JSON; demcal-study/1 is still read)")
      ->required()
      ->check(NonEmpty());
  app->add_option("--out", options->out_dir,
                  "output directory; holds the journal: run again with the same --out to resume")
      ->required()
      ->check(NonEmpty());
  app->add_flag("--quick", options->quick, "run at the experiment file's quick fidelity");
  app->add_option("--max-evaluations", options->max_evaluations,
                  "candidate budget (default: the study's optimiser.max_evaluations)")
      ->check(CliRange<int>(limits::kMaxEvaluations));
  app->add_option("--threads", options->threads, "replicates run side by side on this many cores (0: all; under mpirun: per rank, 0: 1)")
      ->check(CliRange<int>(limits::kThreads));
  app->add_option("--run-time-limit-s", options->run_time_limit_s,
                  "under mpirun: a run going longer is copied to another rank, the first result "
                  "kept (0: 4 x the median run time)")
      ->check(CLI::Range(0.0, 1e7));  // only this option reads it: not in the limits table
  app->add_flag("--quiet", options->quiet, "no progress lines on stderr");
  return {app, [options] { return RunCalibrate(*options, std::cerr); }};
}

}  // namespace demcal::apps
