#include "workflow/calibration/calibration_plots.h"

#include <algorithm>
#include <cmath>

#include "objectives/report/svg_plot.h"

namespace demcal::workflow {
namespace {

using calibrate::Candidate;
using calibrate::CalibrationSummary;
using objectives::PlotSeries;
using objectives::SvgPlot;

objectives::SvgPlot TargetsPlot(const CalibrationSummary& s) {
  SvgPlot plot{.title = "targets at the best candidate (standardised: (value - measured) / u)",
               .x_label = "target number (result.json targets, from 1)",
               .y_label = "standardised residual"};
  for (size_t k = 0; k < s.residuals.size(); ++k) {
    const calibrate::TargetResidual& r = s.residuals[k];
    const double x = static_cast<double>(k + 1), noise = r.uncertainty > 0 ? r.sem / r.uncertainty : 0;
    plot.series.push_back({.label = k ? "" : "measured +- u", .x = {x - 0.1, x - 0.1}, .y = {-1, 1},
                           .color = "#d62728", .width_px = 3});
    plot.series.push_back({.label = k ? "" : "simulated +- sem", .x = {x + 0.1, x + 0.1},
                           .y = {r.residual - noise, r.residual + noise}, .color = "#1f77b4", .width_px = 3});
    plot.series.push_back({.label = "", .x = {x + 0.1}, .y = {r.residual}, .color = "#1f77b4", .dots = true,
                           .width_px = 4});
  }
  const double n = static_cast<double>(s.residuals.size());
  plot.series.push_back({.label = "", .x = {0.5, n + 0.5}, .y = {0, 0}, .color = "#7f7f7f", .dashed = true});
  return plot;
}

objectives::SvgPlot ConvergencePlot(const CalibrationSummary& s) {
  SvgPlot plot{.title = "convergence", .x_label = "candidate (in the order asked)",
               .y_label = "cost = sum of standardised residuals^2 (log10)"};
  PlotSeries all{.label = "candidate", .dots = true, .width_px = 3};
  PlotSeries best{.label = "best so far", .color = "#d62728"};
  double lowest = INFINITY;
  for (const Candidate& c : s.candidates) {
    if (!c.trial.ok) continue;
    const double cost = std::log10(std::max(c.trial.Cost(), 1e-12));
    lowest = std::min(lowest, cost);
    all.x.push_back(c.index), all.y.push_back(cost);
    best.x.push_back(c.index), best.y.push_back(lowest);
  }
  plot.series = {all, best};
  return plot;
}

objectives::SvgPlot ProfilePlot(const calibrate::ParameterSpace& space, const CalibrationSummary& s, size_t k) {
  const calibrate::Parameter& p = space.parameters[k];
  SvgPlot plot{.title = "objective profile along " + p.name, .x_label = p.name,
               .y_label = "cost = sum of standardised residuals^2 (log10)"};
  PlotSeries all{.label = "candidate", .dots = true, .width_px = 3};
  for (const Candidate& c : s.candidates)
    if (c.trial.ok) all.x.push_back(c.parameters[k]), all.y.push_back(std::log10(std::max(c.trial.Cost(), 1e-12)));
  plot.series = {all};
  if (s.best >= 0) {
    const Candidate& b = s.candidates[s.best];
    plot.series.push_back({.label = "best", .x = {b.parameters[k]},
                           .y = {std::log10(std::max(b.trial.Cost(), 1e-12))}, .color = "#d62728",
                           .dots = true, .width_px = 6});
  }
  return plot;
}

// Candidates on the plane of parameters 0 and 1, one series per cost quartile.
objectives::SvgPlot PlanePlot(const calibrate::ParameterSpace& space, const CalibrationSummary& s) {
  SvgPlot plot{.title = "candidates on the parameter plane, coloured by cost",
               .x_label = space.parameters[0].name, .y_label = space.parameters[1].name};
  std::vector<double> costs;
  for (const Candidate& c : s.candidates)
    if (c.trial.ok) costs.push_back(c.trial.Cost());
  std::sort(costs.begin(), costs.end());
  const char* colors[] = {"#2ca02c", "#bcbd22", "#ff7f0e", "#d62728"};
  const char* labels[] = {"lowest cost quarter", "second quarter", "third quarter", "highest quarter"};
  std::vector<PlotSeries> bins(4);
  for (int q = 0; q < 4; ++q) bins[q] = {.label = labels[q], .color = colors[q], .dots = true, .width_px = 4};
  for (const Candidate& c : s.candidates) {
    if (!c.trial.ok) continue;
    const auto rank = std::lower_bound(costs.begin(), costs.end(), c.trial.Cost()) - costs.begin();
    const int q = std::min(3, static_cast<int>(4 * rank / std::max<size_t>(1, costs.size())));
    bins[q].x.push_back(c.parameters[0]), bins[q].y.push_back(c.parameters[1]);
  }
  PlotSeries failed{.label = "no value", .color = "#7f7f7f", .dots = true, .width_px = 2};
  for (const Candidate& c : s.candidates)
    if (!c.trial.ok) failed.x.push_back(c.parameters[0]), failed.y.push_back(c.parameters[1]);
  for (const PlotSeries& b : bins)
    if (!b.x.empty()) plot.series.push_back(b);
  if (!failed.x.empty()) plot.series.push_back(failed);
  return plot;
}

// One parameter, one target: the observable against the parameter, with the measured band.
objectives::SvgPlot ObservablePlot(const StudyFile& st, const CalibrationSummary& s) {
  const calibrate::Parameter& p = st.space.parameters[0];
  const calibrate::Target& t = st.targets[0].target;
  SvgPlot plot{.title = "calibration: " + t.observable + " vs " + p.name,
               .x_label = p.name + " (" + calibrate::PairPropertyKey(p.property) + ", " +
                          st.parameter_materials[0].first + "-" + st.parameter_materials[0].second + ")",
               .y_label = t.observable};
  PlotSeries sim{.label = "simulated (mean)", .dots = true, .width_px = 4};
  PlotSeries up{.label = "mean +- sem", .color = "#7f7f7f", .dots = true, .width_px = 2};
  PlotSeries down{.label = "", .color = "#7f7f7f", .dots = true, .width_px = 2};
  for (const Candidate& c : s.candidates) {
    if (!c.result.ok()) continue;
    const calibrate::TargetValue& v = c.result.targets[0];
    sim.x.push_back(c.parameters[0]), sim.y.push_back(v.mean);
    up.x.push_back(c.parameters[0]), up.y.push_back(v.mean + v.sem);
    down.x.push_back(c.parameters[0]), down.y.push_back(v.mean - v.sem);
  }
  const double m = t.value, u = t.uncertainty;
  const std::vector<double> xs{p.lower, p.upper};
  plot.series = {{.label = "measured", .x = xs, .y = {m, m}, .color = "#d62728"},
                 {.label = "measured +- u", .x = xs, .y = {m + u, m + u}, .color = "#d62728", .dashed = true},
                 {.label = "", .x = xs, .y = {m - u, m - u}, .color = "#d62728", .dashed = true},
                 sim, up, down};
  return plot;
}

// File names from parameter names: letters, digits, '_' and '-' kept, the rest '_'.
std::string FileSafe(const std::string& name) {
  std::string out = name;
  for (char& c : out)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_' && c != '-') c = '_';
  return out;
}

}  // namespace

bool WriteCalibrationPlots(const std::string& dir, const StudyFile& st, const CalibrationSummary& s,
                           std::string* error) {
  if (!objectives::WriteSvg(dir + "/targets.svg", TargetsPlot(s), error)) return false;
  if (!objectives::WriteSvg(dir + "/convergence.svg", ConvergencePlot(s), error)) return false;
  for (size_t k = 0; k < st.space.Size(); ++k)
    if (!objectives::WriteSvg(dir + "/profile_" + FileSafe(st.space.parameters[k].name) + ".svg",
                              ProfilePlot(st.space, s, k), error))
      return false;
  if (st.space.Size() >= 2 && !objectives::WriteSvg(dir + "/parameter_plane.svg", PlanePlot(st.space, s), error))
    return false;
  if (st.space.Size() == 1 && st.targets.size() == 1 &&
      !objectives::WriteSvg(dir + "/calibration.svg", ObservablePlot(st, s), error))
    return false;
  return true;
}

}  // namespace demcal::workflow
