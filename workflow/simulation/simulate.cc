#include "workflow/simulation/simulate.h"

#include <tbb/info.h>

#include <chrono>
#include <cmath>
#include <iostream>
#include <memory>
#include <numeric>

#include "files/json_fields.h"
#include "outputs/exit_codes.h"
#include "outputs/earlier_outputs.h"
#include "outputs/mass_flow_log.h"
#include "outputs/output_lock.h"
#include "outputs/progress_reporter.h"
#include "outputs/run_outputs.h"
#include "files/scene_json.h"
#include "outputs/summary_json.h"
#include "core/simulation/simulation.h"

namespace demcal::workflow {
namespace {

// The observer runs at least this often (in steps) for progress; snapshot cadences are kept
// exact by using a divisor of both.
constexpr int64_t kProgressEverySteps = 16;

double SecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

int ResolveThreads(int requested) {
  return requested > 0 ? requested : tbb::info::default_concurrency();
}

// Steps between checkpoints; 0 when none are asked for.
int64_t CheckpointEverySteps(double every_s, double timestep_s) {
  return every_s > 0 ? std::max<int64_t>(1, std::llround(every_s / timestep_s)) : 0;
}

// The observer cadence: a divisor of every periodic action's cadence (0 = no such action).
int64_t ObserverEverySteps(std::initializer_list<int64_t> cadences) {
  int64_t every = kProgressEverySteps;
  for (int64_t c : cadences)
    if (c > 0) every = std::gcd(every, c);
  return every;
}

// A final checkpoint is worth keeping when the state is sound: the run completed or only ran
// out of wall time (the case a restart is for). After a NaN or a blow-up the last periodic
// checkpoint stays.
bool StateWorthCheckpointing(core::Termination t) {
  return t == core::Termination::kOk || t == core::Termination::kWallTimeExceeded;
}

}  // namespace

bool SimulateOptions::IsValid(std::string* error) const {
  std::string problem;
  if (scene_path.empty())
    problem = "the scene file path is empty";
  else if (out_dir.empty())
    problem = "--out: the output directory is empty";
  else if (threads < 0)
    problem = "--threads = " + std::to_string(threads) + " must be >= 0";
  else if (!(progress_interval_s > 0))
    problem = "--progress-interval-s must be > 0";
  else if (!(checkpoint_every_s >= 0) || !std::isfinite(checkpoint_every_s))
    problem = "--checkpoint-every-s = " + FormatNumber(checkpoint_every_s) +
              " must be >= 0 (0: no checkpoints)";
  if (!problem.empty() && error) *error = problem;
  return problem.empty();
}

int RunSimulate(const SimulateOptions& options, std::ostream& log) {
  const auto start = std::chrono::steady_clock::now();
  std::string error;
  if (!options.IsValid(&error)) {
    log << "error: " << error << "\n";
    return kExitInvalidInput;
  }
  RunRecord record;
  record.scene_path = options.scene_path;
  record.threads_requested = options.threads;
  record.threads_used = ResolveThreads(options.threads);

  // One process per output directory, before anything is written there.
  OutputLock lock;
  if (!LockOutputDirectory(options.out_dir, "demcal simulate " + options.scene_path, &lock,
                           &error)) {
    log << "error: " << error << "\n";
    return kExitInvalidInput;
  }
  SceneFile file;
  std::string scene_error;
  const bool loaded = LoadSceneFile(options.scene_path, &file, &scene_error);
  // The output directory comes first so that even an invalid scene leaves a summary.json.
  RunOutputs outputs(options.out_dir, loaded ? file.output : OutputSettings{});
  if (!outputs.Prepare(&error)) {
    if (!loaded) log << "error: " << scene_error << "\n";
    log << "error: " << error << "\n";
    return loaded ? kExitOutputError : kExitInvalidInput;
  }
  MassFlowLog flow(options.out_dir + "/mass_flow.csv",
                   loaded ? file.output : OutputSettings{});
  bool flow_written = false;
  auto finish = [&](int code) {
    record.total_wall_time_s = SecondsSince(start);
    // A rejected run wrote nothing but this summary.
    record.outputs = record.summary.termination == core::Termination::kInvalidScene
                         ? nlohmann::ordered_json::object()
                         : outputs.Describe();
    if (flow_written) record.outputs["mass_flow_csv"] = "mass_flow.csv";
    std::string write_error;
    if (!WriteRunSummaryJson(outputs.SummaryPath(), record, &write_error)) {
      log << "error: " << write_error << "\n";
      return kExitOutputError;
    }
    return code;
  };
  auto invalid = [&](const std::string& message) {
    log << "error: " << message << "\n";
    // The folder must not look like a finished run of this input (earlier_outputs.h).
    std::string move_error;
    if (!SetAsideEarlierOutputs(options.out_dir, {options.scene_path, options.restart_path},
                                &record.earlier_outputs_moved, &move_error))
      log << "error: " << move_error << "\n";
    else if (!record.earlier_outputs_moved.empty())
      log << "note: the earlier outputs in " << options.out_dir << " were moved to "
          << options.out_dir << "/" << kPreviousRunDir << "/\n";
    record.summary.termination = core::Termination::kInvalidScene;
    record.summary.message = message;
    return finish(kExitInvalidInput);
  };
  if (!loaded) return invalid(scene_error);
  record.seed = file.scene.seed;
  record.requested_duration_s = file.scene.time.duration_s;
  record.scene_description = file.description;

  const double duration_s = file.scene.time.duration_s;
  core::Simulation sim(file.scene, {.threads = options.threads});
  if (!sim.Initialize(&error)) return invalid(options.scene_path + ": " + error);
  const bool restart = !options.restart_path.empty();
  if (restart) {
    if (!sim.LoadCheckpoint(options.restart_path, &error)) return invalid(error);
    record.restarted_from = RunRecord::Restart{options.restart_path, sim.time_s(), sim.steps()};
  }
  record.setup_wall_time_s = SecondsSince(start);
  // Steps still to take: an uninterrupted run takes round(duration / Δt) steps in all.
  const int64_t steps_left =
      std::max<int64_t>(0, std::llround(duration_s / sim.timestep_s()) - sim.steps());
  if (!options.quiet) {
    log << "demcal simulate: " << options.scene_path << ": " << sim.particles().Size()
        << " particles, time step " << sim.timestep_s() << " s, " << steps_left << " steps to "
        << duration_s << " s";
    if (restart) log << " from the checkpoint at t = " << sim.time_s() << " s";
    log << " on " << record.threads_used << " thread(s)\n";
  }
  if (!restart) flow.Record(sim);
  if (restart && !flow.ResumeFrom(sim, &error)) {
    record.output_error = error;
    log << "error: " << error << "\n";
    return finish(kExitOutputError);
  }
  if (!outputs.CopyScene(options.scene_path, &error) ||
      !(restart ? outputs.ResumeFrom(sim, &error) : outputs.WriteSnapshot(sim, &error))) {
    record.output_error = error;
    log << "error: " << error << "\n";
    return finish(kExitOutputError);
  }

  ProgressReporter progress(log, duration_s,
                            {.interval_s = options.progress_interval_s,
                             .enabled = !options.quiet,
                             .start_time_s = sim.time_s()});
  const int64_t snapshot_every = outputs.SnapshotEverySteps(sim.timestep_s());
  const int64_t checkpoint_every =
      CheckpointEverySteps(options.checkpoint_every_s, sim.timestep_s());
  std::string run_output_error;  // an output that failed during the run stops it
  core::Simulation::Observer observer;
  const int64_t flow_every = flow.EverySteps(sim.timestep_s());
  observer.every_steps = ObserverEverySteps({snapshot_every, checkpoint_every, flow_every});
  observer.callback = [&](const core::Simulation& s) {
    if (snapshot_every > 0 && s.steps() % snapshot_every == 0 &&
        !outputs.WriteSnapshot(s, &run_output_error))
      return false;
    if (flow_every > 0 && s.steps() % flow_every == 0) flow.Record(s);
    if (checkpoint_every > 0 && s.steps() % checkpoint_every == 0 &&
        !(outputs.WriteCheckpoint(s, &run_output_error) && flow.Flush(s, &run_output_error)))
      return false;
    progress.Update(s.time_s(), static_cast<int64_t>(s.particles().Size()));
    return true;
  };
  record.summary = sim.Run(static_cast<double>(steps_left) * sim.timestep_s(), observer);
  record.factories = sim.FactoryReports();
  record.factory_warnings = sim.FactoryRateWarnings();
  if (!options.quiet)
    for (const std::string& warning : record.factory_warnings) log << "warning: " << warning << "\n";
  record.sinks = sim.SinkReports();
  for (const core::Species& species : sim.scene().species) record.species_names.push_back(species.name);
  {
    const std::vector<core::WallLoad> loads = sim.WallLoads();
    for (size_t i = 0; i < loads.size() && i < sim.walls().size(); ++i)
      record.wall_loads.push_back({sim.walls()[i].name, loads[i]});
  }

  // The final state is written for failed runs too: it shows where things went wrong.
  flow.Record(sim);
  if (!run_output_error.empty())
    record.output_error = run_output_error;
  else if (!outputs.WriteFinal(sim, &error))
    record.output_error = error;
  else if (!flow.Flush(sim, &error))
    record.output_error = error;
  else if (checkpoint_every > 0 && StateWorthCheckpointing(record.summary.termination) &&
           !outputs.WriteCheckpoint(sim, &error))
    record.output_error = error;
  flow_written = flow.enabled() && record.output_error.empty();

  int code = kExitOk;
  if (!record.output_error.empty()) {
    log << "error: " << record.output_error << "\n";
    code = kExitOutputError;
  } else if (!record.summary.ok()) {
    log << "error: run failed (" << core::TerminationName(record.summary.termination)
        << "): " << record.summary.message << "\n";
    code = kExitRunFailed;
  }
  if (!options.quiet)
    log << "demcal simulate: " << record.summary.BriefReport() << "; outputs in " << options.out_dir
        << "\n";
  return finish(code);
}

}  // namespace demcal::workflow
