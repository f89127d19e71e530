#include "objectives/report/cov_layer_plot_svg.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "objectives/report/svg_canvas.h"

namespace demcal::objectives {
namespace {

constexpr double kLeft = 60, kRight = 130, kTop = 20, kBottom = 45;  // plot margins, px

const SegregationIndex& Pick(const SpeciesSegregation& s, bool by_mass) {
  return by_mass ? s.mass : s.number;
}

const IndexFloor* PickFloor(const HeapFloor* floor, int layer, size_t species, bool by_mass) {
  if (!floor || layer >= static_cast<int>(floor->layers.size())) return nullptr;
  const RegionFloor& region = floor->layers[layer];
  if (species >= region.species.size()) return nullptr;
  const IndexFloor& f = by_mass ? region.species[species].mass : region.species[species].number;
  return f.defined ? &f : nullptr;
}

double LargestCov(const HeapSegregation& heap, const HeapFloor* floor, bool by_mass) {
  double top = 0;
  for (int layer = 0; floor && layer < static_cast<int>(floor->layers.size()); ++layer)
    for (size_t s = 0; s < floor->layers[layer].species.size(); ++s)
      if (const IndexFloor* f = PickFloor(floor, layer, s, by_mass)) top = std::max(top, f->cov_high);
  for (const RegionSegregation& layer : heap.layers)
    for (const SpeciesSegregation& s : layer.species) top = std::max(top, Pick(s, by_mass).cov_m);
  for (const SpeciesSegregation& s : heap.whole.species)
    top = std::max(top, Pick(s, by_mass).cov_m);
  return top > 0 ? top * 1.1 : 1.0;
}

std::string Label(double v) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "%.2f", v);
  return buf;
}

void DrawAxes(SvgCanvas& svg, const LinearMap& px_x, const LinearMap& px_y, int layers,
              double y_top, const CovLayerPlotOptions& o) {
  svg.Line(kLeft, o.height_px - kBottom, o.width_px - kRight, o.height_px - kBottom, "black");
  svg.Line(kLeft, kTop, kLeft, o.height_px - kBottom, "black");
  for (int layer = 1; layer <= layers; ++layer)
    svg.Text(px_x(layer), o.height_px - kBottom + 16, std::to_string(layer), 11, "middle");
  for (int tick = 0; tick <= 4; ++tick) {
    const double v = y_top * tick / 4;
    svg.Line(kLeft - 4, px_y(v), kLeft, px_y(v), "black");
    svg.Text(kLeft - 6, px_y(v) + 4, Label(v), 11, "end");
  }
  svg.Text((kLeft + o.width_px - kRight) / 2, o.height_px - 8, "layer (1 = front face)", 12,
           "middle");
  svg.Text(14, kTop - 6, o.by_mass ? "CoV of mass fraction" : "CoV of number fraction", 12);
}

// The random-mixture band of one species: high edge left to right, low edge back.
void DrawBand(SvgCanvas& svg, const LinearMap& px_x, const LinearMap& px_y, const HeapFloor* floor,
              int layers, size_t species, const std::string& colour, bool by_mass) {
  std::vector<std::pair<double, double>> high, low;
  for (int layer = 0; layer < layers; ++layer) {
    const IndexFloor* f = PickFloor(floor, layer, species, by_mass);
    if (!f) continue;
    high.emplace_back(px_x(layer + 1), px_y(f->cov_high));
    low.emplace_back(px_x(layer + 1), px_y(f->cov_low));
  }
  if (high.size() < 2) return;
  high.insert(high.end(), low.rbegin(), low.rend());
  svg.Polygon(high, colour, 0.15);
}

SvgCanvas DrawPlot(const HeapSegregation& heap, const HeapFloor* floor,
                   const std::vector<std::string>& names, const CovLayerPlotOptions& o) {
  SvgCanvas svg(o.width_px, o.height_px);
  const int layers = static_cast<int>(heap.layers.size());
  const double y_top = LargestCov(heap, floor, o.by_mass);
  const LinearMap px_x{0.5, layers + 0.5, kLeft, o.width_px - kRight};
  const LinearMap px_y{0, y_top, o.height_px - kBottom, kTop};
  DrawAxes(svg, px_x, px_y, layers, y_top, o);
  for (size_t s = 0; s < heap.whole.species.size(); ++s) {
    const std::string colour = s < o.species_colours.size() ? o.species_colours[s] : "black";
    DrawBand(svg, px_x, px_y, floor, layers, s, colour, o.by_mass);
    std::vector<std::pair<double, double>> line;
    for (int layer = 0; layer < layers; ++layer) {
      const SegregationIndex& index = Pick(heap.layers[layer].species[s], o.by_mass);
      if (!index.defined) continue;
      line.emplace_back(px_x(layer + 1), px_y(index.cov_m));
      svg.Circle(line.back().first, line.back().second, 3, colour, colour);
    }
    if (line.size() > 1) svg.Polyline(line, colour);
    const SegregationIndex& whole = Pick(heap.whole.species[s], o.by_mass);
    if (whole.defined)
      svg.Line(kLeft, px_y(whole.cov_m), o.width_px - kRight, px_y(whole.cov_m), colour, 1, "5,4");
    const double legend_y = kTop + 18.0 * static_cast<double>(s + 1);
    svg.Line(o.width_px - kRight + 10, legend_y - 4, o.width_px - kRight + 30, legend_y - 4, colour,
             2);
    svg.Text(o.width_px - kRight + 34, legend_y, s < names.size() ? names[s] : std::to_string(s),
             11);
  }
  svg.Text(o.width_px - kRight + 10, kTop + 18.0 * (heap.whole.species.size() + 1.5),
           "dashed: whole heap", 10);
  if (floor)
    svg.Text(o.width_px - kRight + 10, kTop + 18.0 * (heap.whole.species.size() + 2.3),
             "band: 95% random", 10);
  return svg;
}

}  // namespace

std::string CovLayerPlotSvg(const HeapSegregation& heap, const HeapFloor* floor,
                            const std::vector<std::string>& species_names,
                            const CovLayerPlotOptions& options) {
  return DrawPlot(heap, floor, species_names, options).Document();
}

bool WriteCovLayerPlotSvg(const std::string& path, const HeapSegregation& heap,
                          const HeapFloor* floor, const std::vector<std::string>& species_names,
                          const CovLayerPlotOptions& options, std::string* error) {
  return DrawPlot(heap, floor, species_names, options).WriteFile(path, error);
}

}  // namespace demcal::objectives
