#include "apps/export_command.h"

#include <iostream>
#include <memory>
#include <string>

#include "apps/cli_checks.h"
#include "workflow/export/run_export.h"

namespace demcal::apps {
namespace {

struct ExportCommandOptions {
  std::string target;
  std::string rolling_conversion = "refuse";
  std::string cohesion_approximation = "none";
  workflow::ExportOptions options;
};

}  // namespace

Command AddExportCommand(CLI::App& parent) {
  auto o = std::make_shared<ExportCommandOptions>();
  CLI::App* app = parent.add_subcommand(
      "export", "Write an experiment as a runnable LIGGGHTS-PUBLIC 3.8 deck (docs/export.md)");
  app->add_option("target", o->target, "the code to export to")
      ->required()
      ->check(CLI::IsMember({"liggghts"}));
  app->add_option("experiment", o->options.experiment_path, "experiment file (demcal-experiment/1)")
      ->required()
      ->check(NonEmpty());
  app->add_option("--out", o->options.out_dir, "output folder for the deck")
      ->required()
      ->check(NonEmpty());
  app->add_option("--params", o->options.params_path,
                  "a calibration's calibrated_params.json, applied to the experiment's model")
      ->check(NonEmpty());
  app->add_option("--fidelity", o->options.fidelity,
                  "full (real sizes and stiffness), file (the file's fidelity) or quick")
      ->check(CLI::IsMember({"full", "file", "quick"}));
  app->add_option("--rolling-conversion", o->rolling_conversion,
                  "cdt rolling friction: refuse, or torque (equal torque on a rolling grain; does "
                  "not reproduce demcal's heap angle, docs/export.md)")
      ->check(CLI::IsMember({"refuse", "torque"}));
  app->add_option("--cohesion-approximation", o->cohesion_approximation,
                  "JKR pairs: none (refuse) or sjkr (another law, docs/export.md)")
      ->check(CLI::IsMember({"none", "sjkr"}));
  app->add_option("--dump-interval-s", o->options.dump_interval_s,
                  "simulated time between particle dumps (s, default 0.1)")
      ->check(CLI::Range(1e-6, 1e3));
  return {app, [o] {
            o->options.law.cdt_torque_conversion = o->rolling_conversion == "torque";
            o->options.law.sjkr_approximation = o->cohesion_approximation == "sjkr";
            return workflow::RunExportLiggghts(o->options, std::cerr);
          }};
}

}  // namespace demcal::apps
