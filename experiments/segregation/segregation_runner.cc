// `demcal experiment segregation`: replicated segregation-heap runs → result.json and, per
// replicate r, the bin and index tables, the tracked granules, a picture of the front face with
// the bin grid, the CoV-per-layer plot and a VTK file of the settled heap.
#include "experiments/segregation/segregation_runner.h"

#include <string>
#include <vector>

#include "experiments/common/experiment_setup.h"
#include "files/json_document.h"
#include "experiments/segregation/segregation_section.h"
#include "experiments/segregation/segregation_result.h"
#include "objectives/report/cov_layer_plot_svg.h"
#include "objectives/report/discharge_csv.h"
#include "objectives/report/discharge_svg.h"
#include "objectives/report/heap_face_svg.h"
#include "objectives/common/replicates.h"
#include "objectives/report/segregation_csv.h"
#include "experiments/segregation/segregation_experiment.h"

namespace demcal::workflow {

namespace {

using objectives::SegregationRun;
using objectives::SegregationSettings;

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
  if (!run.outflow.empty()) {  // Fig. 16: what left the funnel, from the first grain out
    objectives::DischargeMetrics m;
    m.composition = run.outflow;
    if (!objectives::WriteCompositionCsv(dir + "/outflow_composition" + k + ".csv", run.outflow, names,
                                         error) ||
        !objectives::WriteSvg(dir + "/outflow_composition" + k + ".svg",
                              objectives::DischargeCompositionPlot(m, run.first_out_s, names), error))
      return false;
  }
  if (!run.analysis) return true;
  const objectives::HeapSegregationAnalysis& a = *run.analysis;
  return objectives::WriteBinCsv(dir + "/segregation_bins" + k + ".csv", a.grid, a.counts, names,
                                 error) &&
         objectives::WriteSegregationCsv(dir + "/segregation_indices" + k + ".csv", a.indices,
                                         names, error) &&
         objectives::WriteHeapFaceSvg(dir + "/heap_front" + k + ".svg", run.heap, a.grid, {},
                                      error) &&
         objectives::WriteCovLayerPlotSvg(dir + "/cov_per_layer" + k + ".svg", a.indices,
                                          run.floor ? &*run.floor : nullptr, names, {}, error);
}

core::Scene BuildScene(const core::Scene& model, const SegregationSettings& settings,
                       uint64_t seed) {
  int64_t fixed = 0;
  return objectives::BuildSegregationScene(model, settings, seed, &fixed);
}

}  // namespace

SegregationResult RunSegregationExperiment(const ExperimentFile& file,
                                           const ExperimentContext& context, std::ostream& log) {
  PreparedExperiment<SegregationSettings> prepared;
  if (!PrepareExperiment(file, context, ParseSegregationSection, BuildScene, &prepared, log))
    return {};
  const SegregationSettings& settings = prepared.settings;
  const std::vector<std::string> names = SpeciesNames(prepared.model);
  std::vector<std::string> output_errors;
  std::vector<SegregationRun> runs = RunPreparedReplicates(
      file, context, prepared, "heap", objectives::RunSegregation,
      [&](int r, const SegregationRun& run, std::string* error) {
        if (error->empty()) WriteRunFiles(context.out_dir, r, run, names, error);
      },
      &output_errors, log);
  SegregationResult out = SummariseSegregation(settings, names, std::move(runs));
  nlohmann::ordered_json result = ResultHeader(file, context);
  result.update(SegregationResultJson(out));
  std::string error = FirstError(output_errors);
  if (!error.empty() || !WriteJsonFile(context.out_dir + "/result.json", result, &error)) {
    log << "error: " << error << "\n";
    out.status = ExperimentStatus::kOutputError;
    return out;
  }
  log << "segregation: " << out.replicates_ok << " of " << context.replicates << " replicates ok";
  for (const SegregationRun& run : out.runs)
    if (!run.ok()) log << "; seed " << run.seed << ": " << run.Status();
  log << " -> " << context.out_dir << "/result.json\n";
  for (const SegregationRun& run : out.runs)
    for (const std::string& warning : run.settle.factory_warnings)
      log << "warning: seed " << run.seed << ": " << warning << "\n";
  out.status = out.replicates_ok > 0 ? ExperimentStatus::kOk : ExperimentStatus::kRunFailed;
  return out;
}

}  // namespace demcal::workflow
