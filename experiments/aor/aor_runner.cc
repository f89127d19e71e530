// `demcal experiment aor`: replicated angle-of-repose runs → result.json, runs.csv, one heap
// profile picture and one VTK file of the settled heap per replicate; the numbers returned as an
// AorResult.
#include "experiments/aor/aor_runner.h"

#include <string>
#include <vector>

#include "experiments/aor/aor_section.h"
#include "experiments/common/experiment_setup.h"
#include "files/json_document.h"
#include "experiments/aor/aor_experiment.h"
#include "objectives/metrics/heap_crest.h"
#include "objectives/report/heap_profile_svg.h"
#include "objectives/common/replicates.h"
#include "objectives/report/text_file.h"

namespace demcal::workflow {

namespace {

using objectives::AorRun;
using objectives::AorSettings;

nlohmann::ordered_json RunJson(int replicate, const AorRun& run) {
  nlohmann::ordered_json j;
  j["replicate"] = replicate;
  j["seed"] = run.seed;
  j["status"] = run.Status();
  j["message"] = run.settle.ok() ? run.angle.message : run.settle.message;
  j["angle_deg"] = run.angle.ok ? nlohmann::ordered_json(run.angle.angle_deg) : nullptr;
  j["flank_spread_deg"] = run.angle.spread_deg;
  j["heap_height_m"] = run.angle.heap_height_m;
  // How far the heap top lies below the apex of the fitted flanks (> 0: a rounded crest); the
  // same number the calibration's crest_drop_m observable reads (experiments/aor/aor_probe.cc).
  j["crest_drop_m"] = run.angle.ok ? nlohmann::ordered_json(objectives::CrestDrop(run.angle, run.angle_options.base_z_m))
                                   : nullptr;
  j["particles"] = run.particles;
  j["settle_time_s"] = run.settle.settle_time_s;
  j["factory_warnings"] = run.settle.factory_warnings;
  j["specific_kinetic_J_kg"] = run.settle.specific_kinetic_J_kg;
  j["settled_by"] = run.settle.settled_by.empty() ? nlohmann::ordered_json() : nlohmann::ordered_json(run.settle.settled_by);
  j["surface_change_d"] = run.settle.surface_change_d >= 0 ? nlohmann::ordered_json(run.settle.surface_change_d) : nlohmann::ordered_json();
  j["wall_time_s"] = run.wall_time_s;
  nlohmann::ordered_json flanks = nlohmann::ordered_json::array();
  for (const objectives::FlankFit& f : run.angle.flanks)
    flanks.push_back({{"label", f.label},
                      {"angle_deg", f.angle_deg},
                      {"r_squared", f.r_squared},
                      {"points", f.points},
                      {"two_point_angle_deg", f.two_point_ok ? nlohmann::ordered_json(f.two_point_angle_deg) : nullptr}});
  j["flanks"] = flanks;
  return j;
}

bool WriteRunsCsv(const std::string& path, const std::vector<AorRun>& runs, std::string* error) {
  return objectives::WriteTextFile(
      path,
      [&](std::ostream& out) {
        out << "replicate,seed,status,angle_deg,flank_spread_deg,flanks,heap_height_m,particles,"
               "settle_time_s,wall_time_s\n";
        for (size_t r = 0; r < runs.size(); ++r) {
          const AorRun& run = runs[r];
          out << r << "," << run.seed << "," << run.Status() << ","
              << (run.angle.ok ? std::to_string(run.angle.angle_deg) : "") << ","
              << run.angle.spread_deg << "," << run.angle.flanks.size() << ","
              << run.angle.heap_height_m << "," << run.particles << ","
              << run.settle.settle_time_s << "," << run.wall_time_s << "\n";
        }
      },
      error);
}

core::Scene BuildScene(const core::Scene& model, const AorSettings& settings, uint64_t seed) {
  int64_t fixed = 0;
  return objectives::BuildAorScene(model, settings, seed, &fixed);
}

objectives::SvgPlot ProfilePlot(const AorSettings& settings, const AorRun& run) {
  if (settings.heap == AorSettings::Heap::kSlot)
    return objectives::SlotHeapProfilePlot(run.heap, run.angle, run.angle_options);
  return objectives::ConicalHeapProfilePlot(run.heap, {0, 0, 0}, run.angle, run.angle_options);
}

nlohmann::ordered_json ResultJson(const ExperimentFile& file, const ExperimentContext& context,
                                  const AorResult& out) {
  nlohmann::ordered_json result = ResultHeader(file, context);
  result["heap"] = out.heap;
  nlohmann::ordered_json runs_json = nlohmann::ordered_json::array();
  for (size_t r = 0; r < out.runs.size(); ++r)
    runs_json.push_back(RunJson(static_cast<int>(r), out.runs[r]));
  const objectives::Summary& s = out.angle_deg;
  result["replicates_ok"] = s.n;
  result["angle_deg"] = s.n > 0 ? nlohmann::ordered_json(s.mean) : nullptr;
  result["angle_sem_deg"] = s.n > 1 ? nlohmann::ordered_json(s.sem) : nullptr;
  result["angle_std_deg"] = s.n > 1 ? nlohmann::ordered_json(s.stddev) : nullptr;
  result["runs"] = runs_json;
  return result;
}

}  // namespace

AorResult RunAorExperiment(const ExperimentFile& file, const ExperimentContext& context,
                           std::ostream& log) {
  AorResult out;
  PreparedExperiment<AorSettings> prepared;
  if (!PrepareExperiment(file, context, ParseAorSection, BuildScene, &prepared, log)) return out;
  const AorSettings& settings = prepared.settings;
  std::vector<std::string> output_errors;
  out.runs = RunPreparedReplicates(
      file, context, prepared, "heap", objectives::RunAor,
      [&](int r, const AorRun& run, std::string* error) {
        if (run.angle.ok)
          objectives::WriteSvg(context.out_dir + "/heap_profile_r" + std::to_string(r) + ".svg",
                               ProfilePlot(settings, run), error);
      },
      &output_errors, log);
  out.heap = settings.heap == AorSettings::Heap::kSlot ? "slot" : "conical";
  std::vector<double> angles;
  for (const AorRun& run : out.runs)
    if (run.ok()) angles.push_back(run.angle.angle_deg);
  out.angle_deg = objectives::Summarise(angles);
  out.replicates_ok = out.angle_deg.n;
  std::string error = FirstError(output_errors);
  if (!error.empty() ||
      !WriteJsonFile(context.out_dir + "/result.json", ResultJson(file, context, out), &error) ||
      !WriteRunsCsv(context.out_dir + "/runs.csv", out.runs, &error)) {
    log << "error: " << error << "\n";
    out.status = ExperimentStatus::kOutputError;
    return out;
  }
  const objectives::Summary& s = out.angle_deg;
  log << "aor: angle of repose " << (s.n > 0 ? std::to_string(s.mean) : "n/a") << " deg ± "
      << s.sem << " (standard error, " << s.n << " of " << context.replicates
      << " replicates ok) -> " << context.out_dir << "/result.json\n";
  for (const AorRun& run : out.runs)
    for (const std::string& warning : run.settle.factory_warnings)
      log << "warning: seed " << run.seed << ": " << warning << "\n";
  out.status = s.n > 0 ? ExperimentStatus::kOk : ExperimentStatus::kRunFailed;
  return out;
}

}  // namespace demcal::workflow
