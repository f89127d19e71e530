// `demcal experiment segregation`: replicated segregation-heap runs → result.json and, per
// replicate r, the bin and index tables, the tracked granules, a picture of the front face with
// the bin grid, the CoV-per-layer plot and a VTK file of the settled heap.
#include <string>
#include <vector>

#include "apps/exit_codes.h"
#include "apps/experiment_runner.h"
#include "apps/replicate_progress.h"
#include "apps/segregation_json.h"
#include "apps/segregation_result.h"
#include "core/io/vtk_writer.h"
#include "objectives/cov_layer_plot_svg.h"
#include "objectives/heap_face_svg.h"
#include "objectives/replicates.h"
#include "objectives/segregation_csv.h"
#include "objectives/segregation_experiment.h"

namespace demcal::apps {

namespace {

using objectives::SegregationRun;
using objectives::SegregationSettings;

std::vector<std::string> SpeciesNames(const core::Scene& model) {
  std::vector<std::string> names;
  for (const core::Species& s : model.species) names.push_back(s.name);
  return names;
}

std::vector<objectives::GranuleTrack> Tracks(const SegregationRun& run) {
  std::vector<objectives::GranuleTrack> tracks;
  for (const objectives::TrackedGranule& g : run.tracked) tracks.push_back(g.track);
  return tracks;
}

// The tables and pictures of one replicate; false with the first error.
bool WriteRunFiles(const std::string& dir, int r, const SegregationRun& run,
                   const std::vector<std::string>& names, std::string* error) {
  const std::string k = "_r" + std::to_string(r);
  if (!objectives::WriteGranuleTracksCsv(dir + "/granule_tracks" + k + ".csv", Tracks(run), error))
    return false;
  if (!run.analysis) return true;
  const objectives::HeapSegregationAnalysis& a = *run.analysis;
  return objectives::WriteBinCsv(dir + "/segregation_bins" + k + ".csv", a.grid, a.counts, names,
                                 error) &&
         objectives::WriteSegregationCsv(dir + "/segregation_indices" + k + ".csv", a.indices,
                                         names, error) &&
         objectives::WriteHeapFaceSvg(dir + "/heap_front" + k + ".svg", run.heap, a.grid, {},
                                      error) &&
         objectives::WriteCovLayerPlotSvg(dir + "/cov_per_layer" + k + ".svg", a.indices, names, {},
                                          error);
}

}  // namespace

int RunSegregationExperiment(const ExperimentFile& file, const ExperimentContext& context,
                             std::ostream& log) {
  core::Scene model = file.model;
  objectives::ApplyFidelity(context.fidelity, &model);
  SegregationSettings settings;
  std::string error;
  if (!ParseSegregationSection(file.section, file.source, model, &settings, &error)) {
    log << "error: " << error << "\n";
    return kExitInvalidInput;
  }
  int64_t fixed = 0;
  const core::Scene probe = objectives::BuildSegregationScene(model, settings, file.seed, &fixed);
  if (!probe.IsValid(&error)) {
    log << "error: " << file.source << ": the segregation scene is invalid: " << error << "\n";
    return kExitInvalidInput;
  }
  const std::vector<std::string> names = SpeciesNames(model);
  std::vector<SegregationRun> runs(context.replicates);
  std::vector<std::string> output_errors(context.replicates);
  ReplicateProgress progress(log, "segregation", context.replicates, !context.quiet);
  objectives::RunReplicates(
      context.replicates, file.seed, context.threads, [&](int r, uint64_t seed) {
        objectives::RunHooks hooks;
        hooks.progress = [&, r](double t, double end) { progress.Update(r, t, end); };
        hooks.on_finish = [&, r](const core::Simulation& sim) {
          const std::string path = context.out_dir + "/heap_r" + std::to_string(r) + ".vtk";
          core::io::WriteParticlesVtk(path, sim.particles(), sim.time_s(), {}, &output_errors[r],
                                      &sim.system().clumps);
        };
        runs[r] = objectives::RunSegregation(model, settings, seed, hooks);
        progress.Finish(r);
        if (output_errors[r].empty())
          WriteRunFiles(context.out_dir, r, runs[r], names, &output_errors[r]);
      });
  nlohmann::ordered_json result = ResultHeader(file, context);
  result.update(SegregationResultJson(settings, names, runs));
  for (const std::string& e : output_errors)
    if (!e.empty()) error = e;
  if (!error.empty() || !WriteJsonFile(context.out_dir + "/result.json", result, &error)) {
    log << "error: " << error << "\n";
    return kExitOutputError;
  }
  const int ok = result["replicates_ok"].get<int>();
  log << "segregation: " << ok << " of " << context.replicates << " replicates ok";
  for (const SegregationRun& run : runs)
    if (!run.ok()) log << "; seed " << run.seed << ": " << run.Status();
  log << " -> " << context.out_dir << "/result.json\n";
  return ok > 0 ? kExitOk : kExitRunFailed;
}

}  // namespace demcal::apps
