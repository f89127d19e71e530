#include "diagnose/report/diagnosis_html.h"

#include <algorithm>
#include <sstream>

#include "diagnose/report/diagnosis_plots.h"
#include "outputs/html_report.h"

namespace demcal::diagnose {
namespace {

std::string Num(double x, int precision = 4) {
  std::ostringstream s;
  s.precision(precision);
  s << x;
  return s.str();
}

bool GapTable(const Diagnosis& d, bool synthetic, workflow::HtmlReport* report,
              std::string* error) {
  workflow::HtmlTable t{
      "standardised residual r = (simulated − measured) / σ per observation and condition",
      {"#", "observable", "condition", "measured ± u", "simulated before", "r before",
       "simulated after", "r after"}};
  for (size_t i = 0; i < d.before.size(); ++i) {
    const Observation& b = d.before[i];
    const bool has_after = i < d.after.size();
    t.rows.push_back({std::to_string(i + 1), b.observable,
                      calibrate::DescribeCondition(b.condition),
                      Num(b.measured) + " ± " + Num(b.uncertainty, 2), Num(b.simulated),
                      Num(b.Residual(), 3), has_after ? Num(d.after[i].simulated) : "",
                      has_after ? Num(d.after[i].Residual(), 3) : ""});
    t.synthetic_rows.push_back(synthetic);
  }
  return report->Table(t, error);
}

// What the data could not see (detection_limits.h): per open candidate, the smallest size its
// own test would have shown at 90 % power.
bool DetectionTable(const DiagnosisRunInfo& info, const Diagnosis& d, bool synthetic,
                    workflow::HtmlReport* report, std::string* error) {
  workflow::HtmlTable t{"smallest effect the data would have shown at " +
                            Num(100 * kDetectionPower, 2) +
                            " % power (linearised at the final fit); smaller ones can hide",
                        {"effect", "parameter", "range", "increase ≥", "decrease ≤",
                         "at half power"}};
  for (const EffectDetection& e : d.detection_limits) {
    const EffectParameter& p = info.candidates[e.candidate].parameters[0];
    const double m = e.limit.magnitude;
    const std::string none = e.has_signature ? "none in range" : "no signature";
    t.rows.push_back({info.candidates[e.candidate].key, p.name + (p.unit.empty() ? "" : " (" + p.unit + ")"),
                      Num(e.lower, 3) + " to " + Num(e.upper, 3),
                      e.upper <= 0 ? "–" : e.has_signature && m <= e.upper ? Num(m, 3) : none,
                      e.lower >= 0 ? "–" : e.has_signature && m <= -e.lower ? Num(-m, 3) : none,
                      e.has_signature ? Num(e.limit.magnitude_half, 3) : "–"});
    t.synthetic_rows.push_back(synthetic);
  }
  return report->Table(t, error);
}

// What became of a step's winner: named, re-valued (model form, joins the fit) or neither (a
// tie, the control guard).
std::string WinnerTag(const Diagnosis& d, int candidate) {
  return d.Named(candidate)      ? " (named)"
         : d.Revalued(candidate) ? " (re-valued, not named)"
                                 : " (best, not named)";
}

bool RankingTable(const DiagnosisRunInfo& info, const Diagnosis& d, const DiagnosisStep& s,
                  workflow::HtmlReport* report, std::string* error) {
  workflow::HtmlTable t{
      s.ranking.message,
      {"rank", "effect", "parameter = value", "direction", "refit", "χ²/dof after", "ΔBIC", "LR p",
       "floor [scatters]", "signature match", "note"}};
  int rank = 1;
  for (int i : s.ranking.order) {
    const RankingEntry& e = s.entries[i];
    const EffectParameter& p = info.candidates[e.candidate].parameters[0];
    t.rows.push_back(
        {std::to_string(rank++) + (i == s.ranking.winner ? WinnerTag(d, e.candidate) : ""), e.key,
         p.name + " = " + (e.values.empty() ? "" : Num(e.values[0], 3)) + " " + p.unit,
         e.values.empty() ? "" : EffectDirection(p, e.values[0]),
         e.simulated ? "simulated" : "linearised", Num(e.chi2_per_dof, 3),
         Num(e.evidence.delta_bic, 3), Num(e.evidence.lr_p_value, 3), Num(e.evidence.floor, 3),
         Num(e.signature_match, 3), e.note});
  }
  return report->Table(t, error);
}

bool CostTable(const Diagnosis& d, workflow::HtmlReport* report, std::string* error) {
  workflow::HtmlTable t{"simulations (replicate runs) and wall time per phase",
                        {"phase", "simulations", "wall time [s]"}};
  for (const PhaseTime& p : d.phases)
    t.rows.push_back({p.phase, std::to_string(p.simulations), Num(p.wall_time_s, 3)});
  t.rows.push_back({"total",
                    std::to_string(d.simulations) + " (+" + std::to_string(d.simulations_reused) +
                        " from journal)",
                    Num(d.wall_time_s, 3)});
  return report->Table(t, error);
}

}  // namespace

bool WriteDiagnosisHtml(const std::string& path, const DiagnosisRunInfo& info, const Diagnosis& d,
                        std::string* error) {
  workflow::HtmlReport report("demcal diagnose " + info.study);
  const bool syn = info.synthetic;
  report.Section("Verdict", syn);
  report.Paragraph(d.message, syn);
  report.Paragraph("Base fit: " + d.base_summary + ".", syn);
  report.Paragraph("Discrepancy floor estimated from the data: " + Num(d.floor_before, 3) +
                       " single-run scatter(s) at the base fit, " + Num(d.floor_after, 3) +
                       " after (beyond the fixed " + Num(info.options.discrepancy_floor) +
                       "); an effect is named only when it explains more than "
                       "this floor allows (docs/diagnose.md).",
                   syn);
  report.Paragraph("Before: " + d.gap_before.summary + ". After" +
                       (d.after_revalued ? " (the re-valued modelled parameter)"
                        : d.after_tied ? " (the worse of the two effects not told apart)"
                                       : "") + ": " +
                       d.gap_after.summary + ".",
                   syn);
  report.Section("Gap before and after", syn);
  if (!report.Figure(objectives::RenderSvg(GapPlot(d)),
                     "standardised residuals before (base model) and after", syn, error) ||
      !GapTable(d, syn, &report, error))
    return false;
  std::vector<std::string> trends;
  for (const CovariateTrend& t : d.gap_before.trends)
    if (t.significant)
      trends.push_back(t.observable + " along " + t.covariate + ": slope " + Num(t.slope, 3) +
                       " ± " + Num(t.slope_sigma, 2) + " per unit (p " + Num(t.p_value, 2) + ")");
  if (!trends.empty()) {
    report.Subheading("Residual trends along the condition covariates (before)");
    report.List(trends);
  }
  for (size_t k = 0; k < d.steps.size(); ++k) {
    report.Section("Candidate effects, step " + std::to_string(k + 1), syn);
    if (!RankingTable(info, d, d.steps[k], &report, error)) return false;
    std::vector<std::string> carried;
    for (const ObservableShare& o : d.steps[k].carried)
      carried.push_back(o.observable + ": χ² gain over the runner-up " +
                        Num(o.against_runner_up, 3) + ", over the base " + Num(o.against_base, 3));
    if (!carried.empty()) {
      report.Subheading("Which observables carried the decision");
      report.List(carried);
    }
  }
  if (!d.detection_limits.empty()) {
    report.Section("What the data could not see", syn);
    if (!DetectionTable(info, d, syn, &report, error)) return false;
  }
  if (!d.steps.empty()) {
    report.Section("Signatures and ranking", syn);
    if (!report.Figure(objectives::RenderSvg(SignaturePlot(info, d)),
                       "signatures of the candidate effects", syn, error) ||
        !report.Figure(objectives::RenderSvg(RankingPlot(d)), "ΔBIC of the candidates", syn, error))
      return false;
  }
  report.Section("Cost");
  if (!CostTable(d, &report, error)) return false;
  std::string provenance;
  for (const std::string& p : info.data_provenance)
    provenance += (provenance.empty() ? "" : ", ") + p;
  report.Paragraph("Data provenance: " + provenance + ".", syn);
  report.Paragraph("Significance " + Num(info.options.significance) + ", model-discrepancy floor " +
                   Num(info.options.discrepancy_floor) + " single-run scatter(s), fidelity " +
                   info.fidelity + ", seed " + std::to_string(info.seed) + ", " +
                   std::to_string(info.replicates) +
                   " replicates. Thresholds and their reasons: docs/diagnose.md.");
  return report.WriteFile(path, error);
}

}  // namespace demcal::diagnose
