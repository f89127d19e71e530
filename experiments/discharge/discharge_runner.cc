// `demcal experiment discharge`: replicated funnel discharges → result.json (discharge time and
// mass flow, mean ± standard error over replicates, and every run), per replicate the outflow
// and composition CSVs and the final state as VTK, and the pictures of the first good run; the
// numbers returned as a DischargeResult.
#include "experiments/discharge/discharge_runner.h"

#include <map>
#include <string>
#include <vector>

#include "experiments/discharge/discharge_section.h"
#include "experiments/common/experiment_setup.h"
#include "files/json_document.h"
#include "objectives/report/discharge_csv.h"
#include "experiments/discharge/discharge_experiment.h"
#include "objectives/report/discharge_svg.h"
#include "objectives/common/replicates.h"

namespace demcal::workflow {

namespace {

using nlohmann::ordered_json;
using objectives::DischargeRun;
using objectives::DischargeSettings;

ordered_json OrNull(bool ok, double value) { return ok ? ordered_json(value) : nullptr; }

ordered_json RunJson(int replicate, const DischargeRun& run) {
  const objectives::DischargeMetrics& m = run.metrics;
  ordered_json j;
  j["replicate"] = replicate;
  j["seed"] = run.seed;
  j["status"] = run.status;
  j["message"] = run.message;
  j["discharge_time_s"] = OrNull(run.ok(), m.discharge_time_s);
  j["mass_flow_kg_s"] = OrNull(run.ok(), m.mass_flow_kg_s);
  j["mass_flow_fit_sem_kg_s"] = OrNull(run.ok(), m.mass_flow_sem_kg_s);
  j["flow_window_s"] = {m.flow_window_start_s, m.flow_window_end_s};
  j["gate_open_s"] = run.gate_open_s;
  j["fill_mass_kg"] = run.fill_mass_kg;
  j["bulk_density_kg_m3"] = run.bulk_density_kg_m3;
  j["particles"] = run.particles;
  j["wall_time_s"] = run.wall_time_s;
  return j;
}

ordered_json HopperJson(const DischargeSettings& s) {
  return {{"fill", s.fill == DischargeSettings::Fill::kPour ? "pour" : "place"},
          {"top_diameter_m", s.hopper.top_diameter_m},
          {"orifice_diameter_m", s.hopper.orifice_diameter_m},
          {"cone_half_angle_deg", s.hopper.cone_half_angle_deg},
          {"cone_height_m", s.hopper.ConeHeightM()},
          {"cylinder_height_m", s.hopper.cylinder_height_m},
          {"catch_depth_m", s.catch_depth_m},
          {"feed_mass_kg", s.feed.mass_kg}};
}

// Mean ± standard error of `value` over the good runs.
objectives::Summary OverOkRuns(const std::vector<DischargeRun>& runs,
                               double (*value)(const DischargeRun&)) {
  std::vector<double> values;
  for (const DischargeRun& run : runs)
    if (run.ok()) values.push_back(value(run));
  return objectives::Summarise(values);
}

// `key` and `sem_key` of a summary: null without a value.
void AddSummary(const objectives::Summary& s, const std::string& key, const std::string& sem_key,
                ordered_json* result) {
  (*result)[key] = OrNull(s.n > 0, s.mean);
  (*result)[sem_key] = OrNull(s.n > 1, s.sem);
}

ordered_json ResultJson(const ExperimentFile& file, const ExperimentContext& context,
                        const DischargeResult& out) {
  ordered_json result = ResultHeader(file, context);
  result["hopper"] = HopperJson(out.settings);
  ordered_json runs_json = ordered_json::array();
  for (size_t r = 0; r < out.runs.size(); ++r)
    runs_json.push_back(RunJson(static_cast<int>(r), out.runs[r]));
  result["replicates_ok"] = out.replicates_ok;
  AddSummary(out.discharge_time_s, "discharge_time_s", "discharge_time_sem_s", &result);
  AddSummary(out.mass_flow_kg_s, "mass_flow_kg_s", "mass_flow_sem_kg_s", &result);
  AddSummary(out.bulk_density_kg_m3, "bulk_density_kg_m3", "bulk_density_sem_kg_m3", &result);
  result["runs"] = runs_json;
  return result;
}

// Per replicate: outflow and composition tables.
void WriteRunTables(const std::string& dir, int r, const DischargeRun& run,
                    const std::vector<std::string>& names, std::string* error) {
  const std::string k = std::to_string(r);
  objectives::WriteOutflowCsv(dir + "/outflow_r" + k + ".csv", run.samples, names, error);
  objectives::WriteCompositionCsv(dir + "/composition_r" + k + ".csv", run.metrics.composition,
                                  names, error);
}

// The pictures of the first run with metrics.
bool WritePictures(const std::string& dir, const std::vector<DischargeRun>& runs,
                   const std::vector<std::string>& names, std::string* error) {
  for (const DischargeRun& run : runs) {
    if (!run.metrics.ok) continue;
    return objectives::WriteSvg(
               dir + "/discharge_mass.svg",
               objectives::DischargeMassPlot(run.samples, run.gate_open_s, run.metrics, names),
               error) &&
           objectives::WriteSvg(
               dir + "/discharge_composition.svg",
               objectives::DischargeCompositionPlot(run.metrics, run.gate_open_s, names), error);
  }
  return true;
}

// The runs that gave no value, by status, with the first message of each: "; 2 jammed (no
// outflow for 0.5 s with ... left in the hopper)". A jammed funnel is a result to report, not
// a slow flow: the console says so, as result.json does per run.
std::string FailedRuns(const std::vector<DischargeRun>& runs) {
  std::map<std::string, std::pair<int, std::string>> by_status;
  for (const DischargeRun& run : runs)
    if (!run.ok()) {
      auto& entry = by_status[run.status];
      if (entry.first++ == 0) entry.second = run.message;
    }
  std::string text;
  for (const auto& [status, entry] : by_status)
    text += "; " + std::to_string(entry.first) + " " + status +
            (entry.second.empty() ? "" : " (" + entry.second + ")");
  return text;
}

}  // namespace

DischargeResult RunDischargeExperiment(const ExperimentFile& file,
                                       const ExperimentContext& context, std::ostream& log) {
  DischargeResult out;
  PreparedExperiment<DischargeSettings> prepared;
  if (!PrepareExperiment(file, context, ParseDischargeSection, objectives::BuildDischargeScene,
                         &prepared, log))
    return out;
  out.settings = prepared.settings;
  const std::vector<std::string> names = SpeciesNames(prepared.model);
  std::vector<std::string> output_errors;
  out.runs = RunPreparedReplicates(
      file, context, prepared, "hopper", objectives::RunDischarge,
      [&](int r, const DischargeRun& run, std::string* error) {
        WriteRunTables(context.out_dir, r, run, names, error);
      },
      &output_errors, log);
  for (const DischargeRun& run : out.runs) out.replicates_ok += run.ok();
  out.discharge_time_s =
      OverOkRuns(out.runs, [](const DischargeRun& x) { return x.metrics.discharge_time_s; });
  out.mass_flow_kg_s =
      OverOkRuns(out.runs, [](const DischargeRun& x) { return x.metrics.mass_flow_kg_s; });
  out.bulk_density_kg_m3 =
      OverOkRuns(out.runs, [](const DischargeRun& x) { return x.bulk_density_kg_m3; });
  const ordered_json result = ResultJson(file, context, out);
  std::string error = FirstError(output_errors);
  if (!error.empty() || !WritePictures(context.out_dir, out.runs, names, &error) ||
      !WriteJsonFile(context.out_dir + "/result.json", result, &error)) {
    log << "error: " << error << "\n";
    out.status = ExperimentStatus::kOutputError;
    return out;
  }
  log << "discharge: mass flow " << result["mass_flow_kg_s"].dump() << " kg/s, discharge time "
      << result["discharge_time_s"].dump() << " s (" << out.replicates_ok << " of "
      << context.replicates << " replicates ok" << FailedRuns(out.runs) << ") -> "
      << context.out_dir << "/result.json\n";
  out.status = out.replicates_ok > 0 ? ExperimentStatus::kOk : ExperimentStatus::kRunFailed;
  return out;
}

}  // namespace demcal::workflow
