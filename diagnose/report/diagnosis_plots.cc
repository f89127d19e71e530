#include "diagnose/report/diagnosis_plots.h"

namespace demcal::diagnose {

using objectives::PlotSeries;
using objectives::SvgPlot;

SvgPlot GapPlot(const Diagnosis& d) {
  SvgPlot plot{.title = "gap before and after (standardised residual per observation)",
               .x_label = "observation (residuals.csv row)", .y_label = "(simulated - measured) / sigma"};
  PlotSeries before{.label = "before (base model)", .color = "#d62728", .dots = true, .width_px = 4};
  PlotSeries after{.label = "after (with the named effects)", .color = "#1f77b4", .dots = true, .width_px = 4};
  for (size_t i = 0; i < d.before.size(); ++i) before.x.push_back(i + 1), before.y.push_back(d.before[i].Residual());
  for (size_t i = 0; i < d.after.size(); ++i) after.x.push_back(i + 1.15), after.y.push_back(d.after[i].Residual());
  const double n = static_cast<double>(d.before.size()) + 0.5, t = d.gap_before.outlier_threshold;
  plot.series = {before, after,
                 {.label = "+-1 sigma", .x = {0.5, n, n, 0.5, 0.5}, .y = {-1, -1, 1, 1, -1}, .color = "#7f7f7f", .dashed = true},
                 {.label = "outlier threshold", .x = {0.5, n}, .y = {t, t}, .color = "#ff7f0e", .dashed = true},
                 {.label = "", .x = {0.5, n}, .y = {-t, -t}, .color = "#ff7f0e", .dashed = true}};
  return plot;
}

SvgPlot SignaturePlot(const DiagnosisRunInfo& info, const Diagnosis& d) {
  SvgPlot plot{.title = "signatures: change of each observation with the effect at its probe value",
               .x_label = "observation (residuals.csv row)", .y_label = "change / sigma"};
  if (d.steps.empty()) return plot;
  const DiagnosisStep& s = d.steps.front();
  for (size_t e = 0; e < s.entries.size(); ++e) {
    PlotSeries series{.label = info.candidates[s.entries[e].candidate].key, .color = objectives::SeriesColor(static_cast<int>(e))};
    for (size_t i = 0; i < s.signatures[e].size() && i < d.before.size(); ++i)
      series.x.push_back(i + 1), series.y.push_back(s.signatures[e][i] / d.before[i].Sigma());
    plot.series.push_back(series);
  }
  PlotSeries gap{.label = "-(residual before): what the gap asks for", .color = "#000000", .dots = true, .width_px = 4};
  for (size_t i = 0; i < d.before.size(); ++i) gap.x.push_back(i + 1), gap.y.push_back(-d.before[i].Residual());
  plot.series.push_back(gap);
  return plot;
}

SvgPlot RankingPlot(const Diagnosis& d) {
  SvgPlot plot{.title = "ranking: delta BIC of each refitted candidate (first step; lower is better)",
               .x_label = "rank (diagnosis.json candidates)", .y_label = "delta BIC"};
  if (d.steps.empty()) return plot;
  const DiagnosisStep& s = d.steps.front();
  PlotSeries simulated{.label = "simulated refit", .color = "#1f77b4", .dots = true, .width_px = 5};
  PlotSeries linear{.label = "linearised refit", .color = "#7f7f7f", .dots = true, .width_px = 3};
  int rank = 1;
  for (int i : s.ranking.order) {
    PlotSeries& p = s.entries[i].simulated ? simulated : linear;
    p.x.push_back(rank++), p.y.push_back(s.entries[i].evidence.delta_bic);
  }
  const double n = static_cast<double>(s.entries.size()) + 0.5;
  plot.series = {simulated, linear, {.label = "0", .x = {0.5, n}, .y = {0, 0}, .color = "#d62728", .dashed = true}};
  return plot;
}

}  // namespace demcal::diagnose
