#include "objectives/report/discharge_svg.h"

#include <numeric>

namespace demcal::objectives {

namespace {

constexpr double kGram = 1e3;

std::string Name(const std::vector<std::string>& names, size_t k) {
  return k < names.size() ? names[k] : "species " + std::to_string(k);
}

}  // namespace

SvgPlot DischargeMassPlot(const std::vector<OutflowSample>& samples, double gate_open_s,
                          const DischargeMetrics& metrics,
                          const std::vector<std::string>& species_names) {
  SvgPlot plot{.title = metrics.ok ? "funnel discharge" : "funnel discharge: " + metrics.message,
               .x_label = "time since the gate opened [s]",
               .y_label = "mass out [g]"};
  const size_t species = samples.empty() ? 0 : samples.front().cumulative_mass_kg.size();
  PlotSeries total{.label = "all", .color = SeriesColor(0), .width_px = 2};
  for (const OutflowSample& s : samples) {
    total.x.push_back(s.time_s - gate_open_s);
    total.y.push_back(
        kGram * std::accumulate(s.cumulative_mass_kg.begin(), s.cumulative_mass_kg.end(), 0.0));
  }
  plot.series.push_back(std::move(total));
  for (size_t k = 0; species > 1 && k < species; ++k) {
    PlotSeries one{.label = Name(species_names, k),
                   .color = SeriesColor(static_cast<int>(k) + 2),
                   .width_px = 1};
    for (const OutflowSample& s : samples) {
      one.x.push_back(s.time_s - gate_open_s);
      one.y.push_back(k < s.cumulative_mass_kg.size() ? kGram * s.cumulative_mass_kg[k] : 0);
    }
    plot.series.push_back(std::move(one));
  }
  if (metrics.ok) {
    PlotSeries fit{.label = "steady flow fit", .color = SeriesColor(1), .dashed = true};
    for (double t : {metrics.flow_window_start_s, metrics.flow_window_end_s}) {
      fit.x.push_back(t - gate_open_s);
      fit.y.push_back(
          kGram * (metrics.mass_flow_intercept_kg + metrics.mass_flow_kg_s * (t - gate_open_s)));
    }
    plot.series.push_back(std::move(fit));
  }
  return plot;
}

SvgPlot DischargeCompositionPlot(const DischargeMetrics& metrics, double gate_open_s,
                                 const std::vector<std::string>& species_names) {
  SvgPlot plot{.title = "outflow composition",
               .x_label = "time since the gate opened [s]",
               .y_label = "mass fraction [-]"};
  const size_t species =
      metrics.composition.empty() ? 0 : metrics.composition.front().mass_fraction.size();
  for (size_t k = 0; k < species; ++k) {
    PlotSeries steps{.label = Name(species_names, k), .color = SeriesColor(static_cast<int>(k))};
    for (const CompositionBin& bin : metrics.composition) {
      const double f = k < bin.mass_fraction.size() ? bin.mass_fraction[k] : 0;
      steps.x.insert(steps.x.end(), {bin.t_start_s - gate_open_s, bin.t_end_s - gate_open_s});
      steps.y.insert(steps.y.end(), {f, f});
    }
    plot.series.push_back(std::move(steps));
  }
  return plot;
}

}  // namespace demcal::objectives
