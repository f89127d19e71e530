#include "apps/diagnose_command.h"

#include <iostream>
#include <memory>

#include "apps/cli_checks.h"
#include "diagnose/run_diagnose.h"

namespace demcal::apps {

namespace limits = objectives::limits;

Command AddDiagnoseCommand(CLI::App& parent) {
  auto o = std::make_shared<diagnose::DiagnoseCommandOptions>();
  CLI::App* app = parent.add_subcommand(
      "diagnose", "Find the gap between a calibrated model and measurements, name the missing effect (demcal-study/2)");
  app->add_option("study", o->study_path, "study file (demcal-study/2 JSON)")
      ->required()
      ->check(NonEmpty());
  app->add_option("--out", o->out_dir, "output directory; holds the journals: run again with the same --out to resume")
      ->required()
      ->check(NonEmpty());
  app->add_flag("--quick", o->quick, "run at the experiment files' quick fidelity");
  app->add_option("--significance", o->diagnose.significance,
                  "level of the gap test and of the evidence for an effect (default 0.01)")
      ->check(InLimit(limits::kSignificance));
  app->add_option("--discrepancy-floor", o->diagnose.discrepancy_floor,
                  "model-discrepancy noise floor in single-run scatters of the simulation (default 1)")
      ->check(InLimit(limits::kDiscrepancyFloor, "single-run scatters"));
  app->add_option("--effects", o->effects, "candidate effects (default: the whole library)")
      ->delimiter(',')
      ->check(NonEmpty());
  app->add_option("--species", o->species, "the species the effects act on (default: from the study's parameters)")
      ->check(NonEmpty());
  app->add_option("--refits", o->diagnose.dem_refits, "candidates refitted by simulation per step (default 2)")
      ->check(CliRange<int>(limits::kDiagnoseRefits));
  app->add_option("--max-effects", o->diagnose.max_effects, "effects added at most (default 2)")
      ->check(CliRange<int>(limits::kDiagnoseMaxEffects));
  app->add_option("--extra-refits", o->diagnose.extra_refits,
                  "re-centred refit points per refitted candidate beyond two, while each lowers its chi2 by >= 1 (default 4)")
      ->check(CliRange<int>(limits::kDiagnoseExtraRefits));
  app->add_flag_callback(
      "--no-screen", [o] { o->diagnose.screen = false; },
      "without a gap, stop at 'no missing effect' instead of screening the candidates' own tests");
  app->add_option("--max-evaluations", o->max_evaluations, "base calibration budget (default: the study's)")
      ->check(CliRange<int>(limits::kMaxEvaluations));
  app->add_option("--threads", o->threads, "runs side by side on this many cores (0: all)")
      ->check(CliRange<int>(limits::kThreads));
  app->add_flag("--quiet", o->quiet, "no progress lines on stderr");
  return {app, [o] { return diagnose::RunDiagnose(*o, std::cerr); }};
}

}  // namespace demcal::apps
