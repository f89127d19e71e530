#include "apps/simulate_command.h"

#include <iostream>
#include <memory>

#include "apps/cli_checks.h"
#include "workflow/simulation/simulate.h"

namespace demcal::apps {

using namespace demcal::workflow;

Command AddSimulateCommand(CLI::App& parent) {
  auto options = std::make_shared<SimulateOptions>();
  CLI::App* sub = parent.add_subcommand(
      "simulate", "Run one scene file (JSON, format demcal-scene/1) and write its outputs");
  sub->add_option("scene", options->scene_path, "scene file, see docs/scene_format.md")
      ->required()
      ->check(NonEmpty());
  sub->add_option("--out,-o", options->out_dir,
                  "output directory (created if missing): summary.json, final_particles.csv, "
                  "vtk/")
      ->required()
      ->check(NonEmpty());
  sub->add_option("--threads,-t", options->threads, "worker threads (0: all cores)")
      ->check(CLI::Range(0, 4096))
      ->capture_default_str();
  sub->add_option("--checkpoint-every-s", options->checkpoint_every_s,
                  "write DIR/checkpoint.bin every S simulated seconds and at the end (0: never)")
      ->check(Seconds(/*allow_zero=*/true, 1e6))
      ->capture_default_str();
  sub->add_option("--restart", options->restart_path,
                  "continue from a checkpoint.bin written for this scene, up to its duration")
      ->check(NonEmpty());
  sub->add_flag("--quiet,-q", options->quiet, "print only errors (no progress, no report)");
  sub->add_option("--progress-interval-s", options->progress_interval_s,
                  "wall time between progress lines on stderr")
      ->check(Seconds(/*allow_zero=*/false, 1e6))
      ->capture_default_str();
  sub->footer(
      "Exit codes: 0 ok, 2 invalid input (nothing ran; also a checkpoint that does not fit the "
      "scene), 3 the run failed (NaN, energy blow-up, "
      "particles lost, wall-time budget), 4 an output could not be written. summary.json is "
      "written in every case but 4. See docs/cli.md.");
  return {sub, [options] { return RunSimulate(*options, std::cerr); }};
}

}  // namespace demcal::apps
