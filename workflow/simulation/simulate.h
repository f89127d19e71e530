#pragma once
// `demcal simulate SCENE.json --out DIR [--threads N] [--quiet] [--checkpoint-every-s S]
// [--restart FILE]`: runs one scene file and writes DIR/summary.json, VTK snapshots and
// DIR/final_particles.csv (see run_outputs.h, docs/cli.md). With --checkpoint-every-s it also keeps
// DIR/checkpoint.bin; --restart continues such a checkpoint to the scene's duration.
//
// RunSimulate is the whole command as a library function (the CLI only parses argv into
// SimulateOptions), so tests and other tools can run scenes without a process.
#include <ostream>
#include <string>

namespace demcal::workflow {

struct SimulateOptions {
  std::string scene_path;            // a "demcal-scene/1" JSON file
  std::string out_dir;               // created if missing; existing files are overwritten
  int threads = 0;                   // worker threads, >= 0 (0: all cores)
  bool quiet = false;                // only errors on the log stream
  double progress_interval_s = 2.0;  // wall time between progress lines, > 0
  // > 0: write DIR/checkpoint.bin every so many simulated seconds (rounded to whole steps) and at
  // the end of the run; 0: no checkpoints.
  double checkpoint_every_s = 0;
  // A checkpoint to continue from: the simulation is initialised from the scene, then takes the
  // checkpoint's state and runs on to the scene's time.duration_s. Empty: start at t = 0.
  std::string restart_path;

  bool IsValid(std::string* error) const;
};

// Runs the command; returns its exit code (exit_codes.h). Progress, the final report and
// errors go to `log`.
int RunSimulate(const SimulateOptions& options, std::ostream& log);

// Adds the `simulate` subcommand to the CLI (see command.h).
}  // namespace demcal::workflow
