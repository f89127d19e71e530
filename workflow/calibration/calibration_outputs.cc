#include "workflow/calibration/calibration_outputs.h"

#include <algorithm>
#include <sstream>

#include "workflow/experiments/experiment_runner.h"
#include "workflow/files/json_document.h"
#include "calibrate/liggghts_export.h"
#include "core/version.h"
#include "objectives/report/svg_plot.h"
#include "objectives/report/text_file.h"

namespace demcal::workflow {
namespace {

using calibrate::CalibrationSummary;
using calibrate::Evaluation;
using Json = nlohmann::ordered_json;

Json Provenance(const CalibrationRunInfo& info, const CalibrationSummary& s) {
  const StudyFile& st = *info.study;
  return {{"demcal_version", kVersion},
          {"study_file", st.source},
          {"experiment_file", st.experiment_path},
          {"measurement", {{"observable", st.measurement.observable},
                           {"value", st.measurement.value},
                           {"uncertainty", st.measurement.uncertainty},
                           {"source", st.measurement.source},
                           {"note", st.measurement_note}}},
          {"fidelity", FidelityJson(info.fidelity)},
          {"seed", info.seed},
          {"replicates", info.replicates},
          {"optimiser", st.options.optimiser},
          {"termination", s.termination}};
}

Json ParameterJson(const CalibrationRunInfo& info, const CalibrationSummary& s, size_t k) {
  const calibrate::Parameter& p = info.study->space.parameters[k];
  const auto& materials = info.study->experiment.model.materials;
  Json j{{"name", p.name},
         {"property", calibrate::PairPropertyKey(p.property)},
         {"materials", {materials[p.material_i].name, materials[p.material_j].name}},
         {"value", s.history[s.best].parameters[k]}};
  j["uncertainty"] = k < s.uncertainty.size() && s.uncertainty[k] > 0 ? Json(s.uncertainty[k]) : Json(nullptr);
  j["sensitivity_per_unit"] = k < s.sensitivity.size() ? Json(s.sensitivity[k]) : Json(nullptr);
  return j;
}

Json ResultJson(const CalibrationRunInfo& info, const CalibrationSummary& s) {
  Json j{{"format", "demcal-calibration/1"}, {"termination", s.termination}, {"message", s.message}};
  j["provenance"] = Provenance(info, s);
  j["candidates"] = s.history.size();
  j["replicates_run"] = s.replicates_run;
  j["replicates_reused"] = s.replicates_reused;
  j["wall_time_s"] = info.wall_time_s;
  if (s.best >= 0) {
    const Evaluation& e = s.history[s.best];
    Json params = Json::array();
    for (size_t k = 0; k < e.parameters.size(); ++k) params.push_back(ParameterJson(info, s, k));
    j["parameters"] = params;
    j["simulated"] = {{"mean", e.summary.mean}, {"sem", e.summary.sem}, {"n", e.summary.n}};
    j["standardised_residual"] = s.best_residual;
  }
  j["uncertainty_note"] = s.uncertainty_note;
  j["journal_error"] = s.journal_error.empty() ? Json(nullptr) : Json(s.journal_error);
  return j;
}

// The calibrated values as entries of an experiment or scene file's "interactions.pairs".
Json ParamsJson(const CalibrationRunInfo& info, const CalibrationSummary& s) {
  Json j{{"format", "demcal-params/1"}, {"provenance", Provenance(info, s)}};
  Json pairs = Json::array(), values = Json::array();
  if (s.best >= 0)
    for (size_t k = 0; k < s.history[s.best].parameters.size(); ++k) {
      const Json p = ParameterJson(info, s, k);
      values.push_back(p);
      pairs.push_back({{"materials", p["materials"]}, {p["property"].get<std::string>(), p["value"]}});
    }
  j["parameters"] = values;
  j["interactions_pairs"] = pairs;
  return j;
}

bool WriteEvaluationsCsv(const std::string& path, const StudyFile& st, const CalibrationSummary& s,
                         std::string* error) {
  return objectives::WriteTextFile(
      path,
      [&](std::ostream& out) {
        out.precision(10);
        out << "candidate";
        for (const auto& p : st.space.parameters)
          out << "," << p.name << (*calibrate::PairPropertyUnit(p.property) ? "_J_m2" : "");
        const std::string obs = st.measurement.observable;
        out << "," << obs << "_mean," << obs << "_sem,replicates_ok,replicates,reused,status\n";
        for (const Evaluation& e : s.history) {
          out << e.index;
          for (double v : e.parameters) out << "," << v;
          out << "," << e.summary.mean << "," << e.summary.sem << "," << e.summary.n << ","
              << e.runs.size() << "," << e.reused << "," << e.status << "\n";
        }
      },
      error);
}

objectives::SvgPlot CalibrationPlot(const StudyFile& st, const CalibrationSummary& s) {
  const calibrate::Parameter& p = st.space.parameters[0];
  const auto& materials = st.experiment.model.materials;
  objectives::SvgPlot plot{.title = "calibration: " + st.measurement.observable + " vs " + p.name,
                           .x_label = p.name + " (" + calibrate::PairPropertyKey(p.property) + ", " +
                                      materials[p.material_i].name + "-" + materials[p.material_j].name + ")",
                           .y_label = st.measurement.observable};
  objectives::PlotSeries sim{.label = "simulated (mean)", .dots = true, .width_px = 4};
  objectives::PlotSeries up{.label = "mean +- sem", .color = "#7f7f7f", .dots = true, .width_px = 2};
  objectives::PlotSeries down{.label = "", .color = "#7f7f7f", .dots = true, .width_px = 2};
  for (const Evaluation& e : s.history) {
    if (!e.ok()) continue;
    sim.x.push_back(e.parameters[0]), sim.y.push_back(e.summary.mean);
    up.x.push_back(e.parameters[0]), up.y.push_back(e.summary.mean + e.summary.sem);
    down.x.push_back(e.parameters[0]), down.y.push_back(e.summary.mean - e.summary.sem);
  }
  const double m = st.measurement.value, u = st.measurement.uncertainty;
  const std::vector<double> xs{p.lower, p.upper};
  plot.series.push_back({.label = "measured", .x = xs, .y = {m, m}, .color = "#d62728"});
  plot.series.push_back({.label = "measured +- u", .x = xs, .y = {m + u, m + u}, .color = "#d62728", .dashed = true});
  plot.series.push_back({.label = "", .x = xs, .y = {m - u, m - u}, .color = "#d62728", .dashed = true});
  plot.series.push_back(sim);
  plot.series.push_back(up);
  plot.series.push_back(down);
  return plot;
}

// The experiment's model with the best candidate's values, as a LIGGGHTS include file.
bool WriteLiggghtsInclude(const std::string& path, const CalibrationRunInfo& info,
                          const CalibrationSummary& s, std::string* error) {
  const StudyFile& st = *info.study;
  core::Scene model = st.experiment.model;
  if (s.best >= 0) st.space.Apply(s.history[s.best].parameters, &model);
  std::ostringstream fidelity;
  fidelity << "calibrated at fidelity '" << info.fidelity.name << "' (size x" << info.fidelity.size_scale
           << ", stiffness x" << info.fidelity.stiffness_scale
           << "); the values below are full scale (Young's moduli of the experiment file)";
  const std::vector<std::string> comments{
      "study: " + st.source + " (termination: " + s.termination + ")",
      "measurement: " + st.measurement.source, fidelity.str(),
      s.best >= 0 ? "calibrated: " + st.space.Describe(s.history[s.best].parameters)
                  : "no calibrated value: the experiment file's values"};
  const std::string deck = calibrate::LiggghtsMaterialInclude(model, comments);
  return objectives::WriteTextFile(path, [&](std::ostream& out) { out << deck; }, error);
}

}  // namespace

bool WriteCalibrationOutputs(const std::string& dir, const CalibrationRunInfo& info,
                             const CalibrationSummary& s, std::string* error) {
  if (!WriteJsonFile(dir + "/result.json", ResultJson(info, s), error)) return false;
  if (!WriteJsonFile(dir + "/calibrated_params.json", ParamsJson(info, s), error)) return false;
  if (!WriteEvaluationsCsv(dir + "/evaluations.csv", *info.study, s, error)) return false;
  if (!WriteLiggghtsInclude(dir + "/calibrated_params.liggghts", info, s, error)) return false;
  if (info.study->space.Size() == 1 &&
      !objectives::WriteSvg(dir + "/calibration.svg", CalibrationPlot(*info.study, s), error))
    return false;
  return true;
}

}  // namespace demcal::workflow
