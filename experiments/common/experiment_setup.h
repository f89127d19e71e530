#pragma once
// What every experiment runner does before and around its replicates (aor_runner.cc,
// discharge_runner.cc, segregation_runner.cc): the model at the run's fidelity with the parsed
// section, checked by building one run's scene before anything runs; the replicates side by
// side with a progress line, each leaving its final state as VTK; the species names for table
// headers.
//
//   PreparedExperiment<AorSettings> p;
//   if (!PrepareExperiment(file, context, ParseAorSection, BuildScene, &p, log))
//     return kExitInvalidInput;
//   std::vector<std::string> errors;
//   std::vector<AorRun> runs = RunPreparedReplicates(file, context, p, "heap", objectives::RunAor,
//                                                    WriteProfile, &errors, log);
#include <ostream>
#include <string>
#include <vector>

#include "experiments/common/experiment_file.h"
#include "experiments/common/experiment_runner.h"
#include "experiments/common/replicate_progress.h"
#include "core/scene/scene.h"
#include "objectives/common/fidelity.h"
#include "objectives/common/replicates.h"
#include "objectives/common/run_hooks.h"

namespace demcal::workflow {

template <class Settings>
struct PreparedExperiment {
  core::Scene model;  // the file's model at the context's fidelity
  Settings settings;  // the experiment's section, checked against that model
};

// Applies the fidelity, parses the section with `parse` (bool(section, source, model,
// Settings*, error*)) and validates the scene `build` (Scene(model, settings, seed)) makes for
// the file's seed. False with "error: ..." logged when either step fails.
template <class Settings, class Parse, class Build>
bool PrepareExperiment(const ExperimentFile& file, const ExperimentContext& context, Parse parse,
                       Build build, PreparedExperiment<Settings>* out, std::ostream& log) {
  out->model = file.model;
  objectives::ApplyFidelity(context.fidelity, &out->model);
  std::string error;
  if (!parse(file.section, file.source, out->model, &out->settings, &error)) {
    log << "error: " << error << "\n";
    return false;
  }
  if (!build(out->model, out->settings, file.seed).IsValid(&error)) {
    log << "error: " << file.source << ": the " << file.experiment << " scene is invalid: " << error
        << "\n";
    return false;
  }
  return true;
}

// Hooks of replicate r: progress into `progress`, and the final state written to
// DIR/<vtk_stem>_r<r>.vtk (a failure goes to *output_error; the run itself goes on).
objectives::RunHooks ReplicateHooks(ReplicateProgress& progress, int r, const std::string& out_dir,
                                    const std::string& vtk_stem, std::string* output_error);

// Runs context.replicates replicates side by side (one per worker; fewer replicates than
// workers share the idle cores as simulation threads): run(model, settings, seed,
// hooks) reporting to one progress line and leaving its final state as
// DIR/<vtk_stem>_r<r>.vtk, then finish(r, result, &error) writes that replicate's own files.
// Returns the results in replicate order; (*output_errors)[r] holds replicate r's first output
// error ("" if none).
template <class Settings, class RunFn, class Finish>
auto RunPreparedReplicates(const ExperimentFile& file, const ExperimentContext& context,
                           const PreparedExperiment<Settings>& prepared,
                           const std::string& vtk_stem, RunFn run, Finish finish,
                           std::vector<std::string>* output_errors, std::ostream& log) {
  using Result =
      decltype(run(prepared.model, prepared.settings, uint64_t{}, objectives::RunHooks{}));
  std::vector<Result> results(context.replicates);
  output_errors->assign(context.replicates, "");
  ReplicateProgress progress(log, file.experiment, context.replicates, !context.quiet);
  const int threads = objectives::ThreadsPerReplicate(context.replicates, context.threads);
  objectives::RunReplicates(
      context.replicates, file.seed, context.threads, [&](int r, uint64_t seed) {
        std::string* error = &(*output_errors)[r];
        objectives::RunHooks hooks = ReplicateHooks(progress, r, context.out_dir, vtk_stem, error);
        hooks.threads = threads;
        results[r] = run(prepared.model, prepared.settings, seed, hooks);
        progress.Finish(r);
        finish(r, results[r], error);
      });
  return results;
}

// The first non-empty message of `errors` ("" when all are empty).
std::string FirstError(const std::vector<std::string>& errors);

std::vector<std::string> SpeciesNames(const core::Scene& model);

}  // namespace demcal::workflow
