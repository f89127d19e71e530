#include "workflow/reproduce/reproduce_plots.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "objectives/report/svg_canvas.h"
#include "objectives/report/svg_plot.h"

namespace demcal::workflow {
namespace {

using objectives::PlotSeries;
using objectives::SeriesColor;
using objectives::SvgPlot;

double Num(const nlohmann::json& j, const char* key) {
  return j.contains(key) && j[key].is_number() ? j[key].get<double>() : NAN;
}

// A vertical error bar at x from y − e to y + e (unlabelled series).
PlotSeries ErrorBar(double x, double y, double e, const std::string& color) {
  return {.x = {x, x}, .y = {y - e, y + e}, .color = color, .width_px = 1.2};
}

std::string Title(const std::string& text, bool synthetic) {
  return synthetic ? text + " [SYNTHETIC angles at some levels]" : text;
}

}  // namespace

std::string GammaCurveSvg(const nlohmann::json& results) {
  if (!results.contains("gamma_per_coating")) return "";
  const nlohmann::json& curve = results.contains("gamma_curve") ? results["gamma_curve"]
                                                                : nlohmann::json::object();
  SvgPlot plot{.x_label = "PEG coating [wt%]", .y_label = "Γ [J/m²]"};
  PlotSeries calibrated{.label = "calibrated Γ ± σ", .color = SeriesColor(0), .dots = true,
                        .width_px = 4};
  PlotSeries synthetic{.label = "calibrated Γ ± σ (SYNTHETIC angle)", .color = "#d08a2a",
                       .dots = true, .width_px = 4};
  std::vector<PlotSeries> bars;
  bool any_synthetic = false;
  for (const nlohmann::json& l : results["gamma_per_coating"]["levels"]) {
    const double w = Num(l, "wt_pct"), g = Num(l, "value"), s = Num(l, "sigma");
    if (!std::isfinite(g)) continue;
    const bool syn = l.value("synthetic", false);
    any_synthetic = any_synthetic || syn;
    (syn ? synthetic : calibrated).x.push_back(w);
    (syn ? synthetic : calibrated).y.push_back(g);
    if (std::isfinite(s)) bars.push_back(ErrorBar(w, g, s, syn ? "#d08a2a" : SeriesColor(0)));
  }
  plot.title = Title("Γ against coating level (paper Fig. 6 style)", any_synthetic);
  if (curve.value("fitted", false)) {
    PlotSeries fit{.label = "fit: " + curve["form"].get<std::string>(), .color = "black"};
    PlotSeries lo{.label = "1σ band", .color = "#888888", .dashed = true};
    PlotSeries hi{.color = "#888888", .dashed = true};
    for (const nlohmann::json& b : curve["band"]) {
      const double w = Num(b, "wt_pct"), g = Num(b, "gamma_J_m2"), s = Num(b, "sigma_J_m2");
      fit.x.push_back(w), fit.y.push_back(g);
      lo.x.push_back(w), lo.y.push_back(g - s);
      hi.x.push_back(w), hi.y.push_back(g + s);
    }
    plot.series = {fit, lo, hi};
  }
  plot.series.push_back({.label = "paper (Fig. 6 text): 0.046, 0.250", .x = {0.5, 2.5},
                         .y = {0.046, 0.250}, .color = "#d62728", .dots = true, .width_px = 3});
  if (!calibrated.x.empty()) plot.series.push_back(calibrated);
  if (!synthetic.x.empty()) plot.series.push_back(synthetic);
  for (const PlotSeries& b : bars) plot.series.push_back(b);
  return objectives::RenderSvg(plot);
}

std::string AngleVsCoatingSvg(const nlohmann::json& results, const std::string& material) {
  if (!results.contains("gamma_per_coating")) return "";
  PlotSeries measured{.label = "measured ± u", .color = "#d62728", .dots = true, .width_px = 4};
  PlotSeries synthetic{.label = "SYNTHETIC ± u", .color = "#d08a2a", .dots = true, .width_px = 4};
  PlotSeries simulated{.label = "demcal at calibrated Γ ± sem", .color = SeriesColor(0),
                       .dots = true, .width_px = 3};
  std::vector<PlotSeries> bars;
  bool any_synthetic = false;
  auto add = [&](double w, const nlohmann::json& o, bool syn) {
    const double m = Num(o, "measured"), u = Num(o, "uncertainty");
    const double s = Num(o, "simulated"), e = Num(o, "sem");
    PlotSeries& target = syn ? synthetic : measured;
    if (std::isfinite(m)) {
      target.x.push_back(w - 0.04), target.y.push_back(m);
      if (std::isfinite(u)) bars.push_back(ErrorBar(w - 0.04, m, u, target.color));
    }
    if (std::isfinite(s)) {
      simulated.x.push_back(w + 0.04), simulated.y.push_back(s);
      if (std::isfinite(e)) bars.push_back(ErrorBar(w + 0.04, s, e, SeriesColor(0)));
    }
  };
  if (results.contains("species") && results["species"]["species"].contains(material))
    add(0, results["species"]["species"][material], false);
  for (const nlohmann::json& l : results["gamma_per_coating"]["levels"]) {
    const bool syn = l.value("synthetic", false);
    any_synthetic = any_synthetic || syn;
    add(Num(l, "wt_pct"), l, syn);
  }
  SvgPlot plot{.title = Title("Repose angle of " + material + " against coating (paper Fig. 7 style)",
                              any_synthetic),
               .x_label = "PEG coating [wt%]", .y_label = "repose angle [deg]"};
  for (const PlotSeries* s : {&measured, &synthetic, &simulated})
    if (!s->x.empty()) plot.series.push_back(*s);
  for (const PlotSeries& b : bars) plot.series.push_back(b);
  return objectives::RenderSvg(plot);
}

std::string SegregationBarsSvg(const nlohmann::json& results, const std::string& material) {
  if (!results.contains("segregation") || !results["segregation"].value("enabled", false))
    return "";
  const nlohmann::json& scenarios = results["segregation"]["scenarios"];
  const std::vector<std::pair<std::string, std::string>> metrics = {
      {".cov_3d", "CoV 3D"}, {".s_n_3d", "S_n 3D"}, {".s_n_2d_front", "S_n front"},
      {".s_n_2d_back", "S_n back"}};
  const double width = 720, height = 380, left = 60, right = 20, top = 40, bottom = 60;
  double y_max = 1.0;
  bool synthetic = false;
  for (const auto& [name, s] : scenarios.items()) {
    synthetic = synthetic || s.value("synthetic", false);
    for (const auto& m : metrics) {
      const std::string key = material + m.first;
      if (s.contains(key)) y_max = std::max(y_max, Num(s[key], "mean") + std::max(0.0, Num(s[key], "sem")));
    }
  }
  y_max = std::isfinite(y_max) ? y_max * 1.15 : 3;
  objectives::SvgCanvas svg(width, height);
  const objectives::LinearMap py{0, y_max, height - bottom, top};
  svg.Text(width / 2, 20, Title(material + " segregation indices per scenario (paper Figs. 10, 12, 13 style)",
                                synthetic), 13, "middle");
  svg.Line(left, height - bottom, width - right, height - bottom, "black");
  svg.Line(left, top, left, height - bottom, "black");
  for (int t = 0; t <= 4; ++t) {
    char label[16];
    std::snprintf(label, sizeof(label), "%.2f", y_max * t / 4);
    svg.Line(left - 4, py(y_max * t / 4), left, py(y_max * t / 4), "black");
    svg.Text(left - 6, py(y_max * t / 4) + 4, label, 11, "end");
  }
  svg.Line(left, py(1), width - right, py(1), "#888888", 1, "4,3");  // S_n = 1: random mixture
  const double group = (width - left - right) / metrics.size();
  const double bar = group / (scenarios.size() + 1);
  for (size_t m = 0; m < metrics.size(); ++m) {
    svg.Text(left + group * (m + 0.5), height - bottom + 18, metrics[m].second, 12, "middle");
    int k = 0;
    for (const auto& [name, s] : scenarios.items()) {
      const std::string key = material + metrics[m].first;
      const double v = s.contains(key) ? Num(s[key], "mean") : NAN;
      const double e = s.contains(key) ? Num(s[key], "sem") : NAN;
      const double x = left + group * m + bar * (k + 0.5);
      if (std::isfinite(v)) {
        svg.Rect(x, py(v), bar * 0.9, py(0) - py(v), SeriesColor(k), "none");
        if (std::isfinite(e))
          svg.Line(x + bar * 0.45, py(v - e), x + bar * 0.45, py(v + e), "black", 1.2);
      }
      ++k;
    }
  }
  int k = 0;
  for (const auto& [name, s] : scenarios.items()) {
    svg.Rect(left + 10 + 130 * k, height - 24, 12, 12, SeriesColor(k), "none");
    svg.Text(left + 26 + 130 * k, height - 14, name, 12);
    ++k;
  }
  svg.Text(width - right, py(1) - 4, "S_n = 1 (random mixture)", 10, "end");
  return svg.Document();
}

}  // namespace demcal::workflow
