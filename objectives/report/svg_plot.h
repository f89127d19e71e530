#pragma once
// SvgPlot: a minimal x–y chart drawn on an SvgCanvas (svg_canvas.h, hand-made SVG), for the
// pictures the experiments leave for users to look at (heap profile with its fitted flanks,
// discharged mass and outflow composition over time). Lines or dots per series, linear axes with
// round ticks, a legend of the labelled series. Non-finite points are skipped. Plain data;
// thread-safe.
//
//   SvgPlot plot{.title = "heap", .x_label = "x [mm]", .y_label = "z [mm]"};
//   plot.series.push_back({.label = "surface", .x = xs, .y = ys, .dots = true});
//   std::string error;
//   if (!WriteSvg("heap.svg", plot, &error)) ...
#include <string>
#include <vector>

namespace demcal::objectives {

struct PlotSeries {
  std::string label;  // empty: not in the legend
  std::vector<double> x, y;
  std::string color = "#1f77b4";
  bool dots = false;  // dots instead of a polyline
  bool dashed = false;
  double width_px = 1.5;  // line width, or dot radius
};

struct SvgPlot {
  std::string title, x_label, y_label;
  std::vector<PlotSeries> series;
  bool equal_aspect = false;  // one data unit is as long on both axes (a heap's true slope)
  int width_px = 720, height_px = 480;
};

std::string RenderSvg(const SvgPlot& plot);

// Writes RenderSvg(plot) to path; false with the reason in *error.
bool WriteSvg(const std::string& path, const SvgPlot& plot, std::string* error);

// Colours for series k = 0, 1, 2, … (cycling).
std::string SeriesColor(int k);

}  // namespace demcal::objectives
