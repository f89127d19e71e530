#include "diagnose/report/diagnosis_outputs.h"

#include <sstream>

#include "diagnose/report/diagnosis_html.h"
#include "diagnose/report/diagnosis_json.h"
#include "diagnose/report/diagnosis_plots.h"
#include "objectives/report/text_file.h"

namespace demcal::diagnose {
namespace {

std::string Csv(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

void ResidualsCsv(const Diagnosis& d, std::ostream& out) {
  out.precision(10);
  out << "row,name,observable,condition,measured,uncertainty,simulated_before,sem_before,floor_"
         "before,"
         "residual_before,simulated_after,sem_after,residual_after\n";
  for (size_t i = 0; i < d.before.size(); ++i) {
    const Observation& b = d.before[i];
    out << i + 1 << "," << Csv(b.name) << "," << b.observable << ","
        << Csv(calibrate::DescribeCondition(b.condition)) << "," << b.measured << ","
        << b.uncertainty << "," << b.simulated << "," << b.sem << "," << b.floor << ","
        << b.Residual();
    if (i < d.after.size())
      out << "," << d.after[i].simulated << "," << d.after[i].sem << "," << d.after[i].Residual();
    else
      out << ",,,";
    out << "\n";
  }
}

void RankingCsv(const DiagnosisRunInfo& info, const Diagnosis& d, std::ostream& out) {
  out.precision(8);
  out << "step,rank,effect,parameter,value,direction,refit,chi2,chi2_per_dof_after,delta_bic,"
         "likelihood_ratio_p,signature_match,"
         "winner\n";
  for (size_t s = 0; s < d.steps.size(); ++s) {
    int rank = 1;
    for (int i : d.steps[s].ranking.order) {
      const RankingEntry& e = d.steps[s].entries[i];
      out << s + 1 << "," << rank++ << "," << e.key << ","
          << info.candidates[e.candidate].parameters[0].name << ","
          << (e.values.empty() ? 0 : e.values[0]) << ","
          << (e.values.empty()
                  ? ""
                  : EffectDirection(info.candidates[e.candidate].parameters[0], e.values[0]))
          << "," << (e.simulated ? "simulated" : "linearised") << "," << e.chi2 << ","
          << e.chi2_per_dof << "," << e.evidence.delta_bic << "," << e.evidence.lr_p_value << ","
          << e.signature_match << "," << (i == d.steps[s].ranking.winner ? 1 : 0) << "\n";
    }
  }
}

void SignaturesCsv(const Diagnosis& d, std::ostream& out) {
  out.precision(10);
  out << "step,effect,row,observable,condition,change_at_probe,change_per_sigma\n";
  for (size_t s = 0; s < d.steps.size(); ++s)
    for (size_t e = 0; e < d.steps[s].entries.size(); ++e)
      for (size_t i = 0; i < d.steps[s].signatures[e].size() && i < d.before.size(); ++i)
        out << s + 1 << "," << d.steps[s].entries[e].key << "," << i + 1 << ","
            << d.before[i].observable << ","
            << Csv(calibrate::DescribeCondition(d.before[i].condition)) << ","
            << d.steps[s].signatures[e][i] << ","
            << d.steps[s].signatures[e][i] / d.before[i].Sigma() << "\n";
}

}  // namespace

bool WriteDiagnosisOutputs(const std::string& dir, const DiagnosisRunInfo& info, const Diagnosis& d,
                           std::string* error) {
  auto json = [](const nlohmann::ordered_json& j) {
    return [j](std::ostream& out) { out << j.dump(2) << "\n"; };
  };
  return objectives::WriteTextFile(dir + "/diagnosis.json", json(DiagnosisJson(info, d)), error) &&
         objectives::WriteTextFile(dir + "/diagnosed_params.json",
                                   json(DiagnosedParamsJson(info, d)), error) &&
         objectives::WriteTextFile(
             dir + "/residuals.csv", [&d](std::ostream& o) { ResidualsCsv(d, o); }, error) &&
         objectives::WriteTextFile(
             dir + "/ranking.csv", [&](std::ostream& o) { RankingCsv(info, d, o); }, error) &&
         objectives::WriteTextFile(
             dir + "/signatures.csv", [&d](std::ostream& o) { SignaturesCsv(d, o); }, error) &&
         objectives::WriteSvg(dir + "/gap.svg", GapPlot(d), error) &&
         objectives::WriteSvg(dir + "/signatures.svg", SignaturePlot(info, d), error) &&
         objectives::WriteSvg(dir + "/ranking.svg", RankingPlot(d), error) &&
         WriteDiagnosisHtml(dir + "/report.html", info, d, error);
}

}  // namespace demcal::diagnose
