#include "workflow/calibration/calibration_outputs.h"

#include <cmath>
#include <sstream>

#include "calibrate/liggghts_export.h"
#include "core/version.h"
#include "objectives/report/text_file.h"
#include "workflow/calibration/calibration_plots.h"
#include "experiments/common/experiment_runner.h"
#include "files/json_document.h"

namespace demcal::workflow {
namespace {

using calibrate::CalibrationSummary;
using Json = nlohmann::ordered_json;

Json Finite(double v) { return std::isfinite(v) ? Json(v) : Json(nullptr); }

Json MatrixJson(const Eigen::MatrixXd& m) {
  Json rows = Json::array();
  for (Eigen::Index i = 0; i < m.rows(); ++i) {
    Json row = Json::array();
    for (Eigen::Index j = 0; j < m.cols(); ++j) row.push_back(Finite(m(i, j)));
    rows.push_back(row);
  }
  return rows;
}

Json Provenance(const CalibrationRunInfo& info, const CalibrationSummary& s) {
  const StudyFile& st = *info.study;
  Json targets = Json::array(), experiments = Json::array();
  for (const StudyTarget& t : st.targets)
    targets.push_back({{"name", t.target.name}, {"observable", t.target.observable},
                       {"value", t.target.value}, {"uncertainty", t.target.uncertainty},
                       {"condition", t.condition}, {"provenance", t.provenance},
                       {"source", t.target.source}, {"note", t.note}});
  for (const StudyExperiment& e : st.experiments)
    experiments.push_back({{"file", e.path}, {"experiment", e.file.experiment}});
  Json j{{"demcal_version", kVersion}, {"study_file", st.source}, {"experiments", experiments},
         {"targets", targets}, {"fidelity", FidelityJson(info.fidelity)}, {"seed", info.seed},
         {"replicates", info.replicates}, {"optimiser", st.options.optimiser},
         {"termination", calibrate::TerminationName(s.termination)}};
  if (info.clump_count > 0)
    j["clump_count"] = {{"species", st.clump_count.species}, {"count", info.clump_count}};
  return j;
}

Json ParameterJson(const StudyFile& st, const CalibrationSummary& s, size_t k) {
  const calibrate::Parameter& p = st.space.parameters[k];
  Json j{{"name", p.name}, {"property", calibrate::PairPropertyKey(p.property)},
         {"materials", {st.parameter_materials[k].first, st.parameter_materials[k].second}}};
  if (!p.when.empty()) j["when"] = p.when;
  if (p.curve >= 0) j["curve"] = st.space.curves[p.curve].name;
  j["value"] = s.best >= 0 ? Json(s.candidates[s.best].parameters[k]) : Json(nullptr);
  const bool estimated = k < s.estimates.size();
  j["sigma"] = estimated ? Finite(s.estimates[k].sigma) : Json(nullptr);
  j["identifiable"] = estimated && s.estimates[k].identifiable;
  return j;
}

Json IdentifiabilityJson(const calibrate::IdentifiabilityReport& r) {
  Json undetermined = Json::array();
  for (const calibrate::UndeterminedDirection& d : r.undetermined)
    undetermined.push_back({{"description", d.description}, {"direction_si", d.si_direction}, {"singular_value", d.singular_value}});
  return {{"singular_values", r.singular_values}, {"condition_number", Finite(r.condition_number)},
          {"undetermined", undetermined}, {"summary", r.summary}};
}

Json GainsJson(const std::vector<calibrate::TargetGain>& gains) {
  Json list = Json::array();
  for (const calibrate::TargetGain& g : gains) {
    Json before = Json::array(), after = Json::array();
    for (double v : g.sigma_before) before.push_back(Finite(v));
    for (double v : g.sigma_after) after.push_back(Finite(v));
    list.push_back({{"name", g.name}, {"sigma_before", before}, {"sigma_after", after},
                    {"lifts_valley", g.lifts_valley}, {"description", g.description}});
  }
  return list;
}

Json ResultJson(const CalibrationRunInfo& info, const CalibrationSummary& s) {
  const StudyFile& st = *info.study;
  Json j{{"format", "demcal-calibration/2"},
         {"termination", calibrate::TerminationName(s.termination)},
         {"message", s.message}};
  j["provenance"] = Provenance(info, s);
  j["candidates"] = s.candidates.size();
  j["batches"] = s.batches;
  j["replicates_run"] = s.replicates_run;
  j["replicates_reused"] = s.replicates_reused;
  j["wall_time_s"] = info.wall_time_s;
  Json params = Json::array(), residuals = Json::array();
  for (size_t k = 0; k < st.space.Size(); ++k) params.push_back(ParameterJson(st, s, k));
  for (const calibrate::TargetResidual& r : s.residuals)
    residuals.push_back({{"name", r.name}, {"observable", r.observable}, {"measured", r.measured},
                         {"uncertainty", r.uncertainty}, {"simulated", r.simulated}, {"sem", r.sem},
                         {"standardised_residual", r.residual}, {"within_noise", r.within_noise}});
  j["parameters"] = params;
  j["targets"] = residuals;
  j["correlation"] = MatrixJson(s.correlation);
  j["covariance_si"] = MatrixJson(s.covariance);
  j["covariance_note"] = s.covariance_note;
  j["sensitivity_matrix"] = {{"rows", "targets, standardised (residual / sqrt(u^2 + sem^2))"},
                             {"columns", "parameters, per unit of the unit cube"},
                             {"values", MatrixJson(s.jacobian)}, {"sigma", MatrixJson(s.jacobian_sigma)},
                             {"note", s.jacobian_note}};
  j["identifiability"] = IdentifiabilityJson(s.identifiability);
  j["local_crossing"] =
      LocalCrossingJson(s.local_crossing, s.local_crossing_value, s.local_crossing_sigma);
  j["candidate_targets"] = GainsJson(info.gains);
  j["journal_error"] = s.journal_error.empty() ? Json(nullptr) : Json(s.journal_error);
  return j;
}

Json ParamsJson(const CalibrationRunInfo& info, const CalibrationSummary& s) {
  const StudyFile& st = *info.study;
  Json j{{"format", "demcal-params/1"}, {"provenance", Provenance(info, s)}};
  Json values = Json::array(), pairs = Json::array();
  for (size_t k = 0; k < st.space.Size(); ++k) {
    const Json p = ParameterJson(st, s, k);
    values.push_back(p);
    if (st.space.parameters[k].curve < 0 && st.space.parameters[k].when.empty() && s.best >= 0)
      pairs.push_back({{"materials", p["materials"]}, {p["property"].get<std::string>(), p["value"]}});
  }
  j["parameters"] = values;
  j["interactions_pairs"] = pairs;  // the global values, ready for an experiment or scene file
  j["covariance_si"] = MatrixJson(s.covariance);
  j["correlation"] = MatrixJson(s.correlation);
  return j;
}

bool WriteEvaluationsCsv(const std::string& path, const CalibrationRunInfo& info, const CalibrationSummary& s,
                         std::string* error) {
  const StudyFile& st = *info.study;
  return objectives::WriteTextFile(
      path,
      [&](std::ostream& out) {
        out.precision(10);
        out << "candidate";
        for (const calibrate::Parameter& p : st.space.parameters)
          out << "," << p.name << (*calibrate::PairPropertyUnit(p.property) && p.curve < 0 ? "_J_m2" : "");
        for (size_t t = 0; t < st.targets.size(); ++t)
          out << ",target" << t << "_" << st.targets[t].target.observable << "_mean,target" << t << "_"
              << st.targets[t].target.observable << "_sem,target" << t << "_replicates_ok";
        out << ",cost,replicates_run,replicates_reused,status\n";
        // A value that does not exist (an infeasible candidate's cost, a target without runs)
        // is an empty cell, as docs/calibration.md says, never "nan".
        auto cell = [&out](double v) -> std::ostream& {
          out << ",";
          return std::isfinite(v) ? out << v : out;
        };
        for (const calibrate::Candidate& c : s.candidates) {
          out << c.index;
          for (double v : c.parameters) cell(v);
          for (const calibrate::TargetValue& v : c.result.targets) {
            cell(v.mean);
            cell(v.sem) << "," << v.replicates;
          }
          cell(c.trial.ok ? c.trial.Cost() : NAN) << "," << c.result.replicates_run << ","
              << c.result.replicates_reused << "," << c.result.status << "\n";
        }
      },
      error);
}

// The first experiment's model with the best candidate's values under the first target's
// condition, as a LIGGGHTS include file.
bool WriteLiggghtsInclude(const std::string& path, const CalibrationRunInfo& info, const CalibrationSummary& s,
                          std::string* error) {
  const StudyFile& st = *info.study;
  core::Scene model = st.experiment().model;
  std::string why;
  calibrate::ParameterSpace space;
  if (s.best >= 0 && ResolveSpaceFor(st, model, &space, &why))
    space.Apply(s.candidates[s.best].parameters, st.targets.front().condition, &model, &why);
  std::ostringstream fidelity;
  fidelity << "calibrated at fidelity '" << info.fidelity.name << "' (size x" << info.fidelity.size_scale
           << ", stiffness x" << info.fidelity.stiffness_scale
           << "); the values below are full scale (Young's moduli of the experiment file)";
  const std::vector<std::string> comments{
      "study: " + st.source + " (termination: " + calibrate::TerminationName(s.termination) + ")",
      "condition: " + calibrate::DescribeCondition(st.targets.front().condition), fidelity.str(),
      s.best >= 0 ? "calibrated: " + st.space.Describe(s.candidates[s.best].parameters)
                  : "no calibrated value: the experiment file's values"};
  const std::string deck = calibrate::LiggghtsMaterialInclude(model, comments);
  return objectives::WriteTextFile(path, [&](std::ostream& out) { out << deck; }, error);
}

}  // namespace

Json LocalCrossingJson(const calibrate::LocalCrossing& line, double value, double sigma) {
  return {{"fitted", line.fitted}, {"matched", line.matched}, {"value", NumOrNull(value)},
          {"sigma", NumOrNull(sigma)}, {"points", line.points}, {"chi_square", line.chi_square},
          {"dof", line.dof},
          {"residual_sigma_in_uncertainties", NumOrNull(line.fitted ? line.residual_sigma : NAN)},
          {"message", line.message}};
}

bool WriteCalibrationOutputs(const std::string& dir, const CalibrationRunInfo& info,
                             const CalibrationSummary& s, std::string* error) {
  return WriteJsonFile(dir + "/result.json", ResultJson(info, s), error) &&
         WriteJsonFile(dir + "/calibrated_params.json", ParamsJson(info, s), error) &&
         WriteEvaluationsCsv(dir + "/evaluations.csv", info, s, error) &&
         WriteLiggghtsInclude(dir + "/calibrated_params.liggghts", info, s, error) &&
         WriteCalibrationPlots(dir, *info.study, s, error);
}

}  // namespace demcal::workflow
