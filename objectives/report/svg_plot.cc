#include "objectives/report/svg_plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "objectives/report/svg_canvas.h"

namespace demcal::objectives {

namespace {

constexpr double kLeft = 80, kTop = 40, kBottom = 60;  // margins, px

// Right margin: room for the longest legend label, so a long one is not cut off at the edge.
// 12 px sans-serif averages under 7 px per character (DejaVu Sans, Chromium's default); the
// legend's line and gap take 45 px. At least 150 px; at most half the width, so a plot remains.
double RightMargin(const SvgPlot& plot) {
  size_t longest = 0;
  for (const PlotSeries& s : plot.series) {
    size_t characters = 0;  // UTF-8 code points: every byte but continuation bytes 10xxxxxx
    for (unsigned char c : s.label) characters += (c & 0xC0) != 0x80;
    longest = std::max(longest, characters);
  }
  return std::clamp(45 + 7.0 * static_cast<double>(longest), 150.0, 0.5 * plot.width_px);
}

// Width of the plot frame: the image less the left and right margins.
double FrameWidth(const SvgPlot& plot) { return plot.width_px - kLeft - RightMargin(plot); }

struct Range {
  double lo = INFINITY, hi = -INFINITY;
  void Add(double v) {
    if (std::isfinite(v)) lo = std::min(lo, v), hi = std::max(hi, v);
  }
  double Span() const { return hi - lo; }
};

// Data bounds with 5% padding; a degenerate range is widened so the axis still has a scale.
void Bounds(const SvgPlot& plot, Range* x, Range* y) {
  for (const PlotSeries& s : plot.series)
    for (size_t i = 0; i < std::min(s.x.size(), s.y.size()); ++i)
      if (std::isfinite(s.x[i]) && std::isfinite(s.y[i])) x->Add(s.x[i]), y->Add(s.y[i]);
  for (Range* r : {x, y}) {
    if (!(r->lo <= r->hi)) r->lo = 0, r->hi = 1;
    if (r->Span() == 0) r->lo -= 0.5 * (1 + std::abs(r->lo)), r->hi += 0.5 * (1 + std::abs(r->hi));
    const double pad = 0.05 * r->Span();
    r->lo -= pad, r->hi += pad;
  }
}

// Stretch the range whose data unit would be drawn longer, so both are drawn alike.
void EqualAspect(double width_px, double height_px, Range* x, Range* y) {
  const double px_per_unit = std::min(width_px / x->Span(), height_px / y->Span());
  auto widen = [](Range* r, double span) {
    const double mid = (r->lo + r->hi) / 2;
    r->lo = mid - span / 2, r->hi = mid + span / 2;
  };
  widen(x, width_px / px_per_unit);
  widen(y, height_px / px_per_unit);
}

// A round tick step (1, 2 or 5 × 10ⁿ) giving about five ticks.
double TickStep(double span) {
  const double raw = span / 5, decade = std::pow(10, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0})
    if (m * decade >= raw) return m * decade;
  return 10 * decade;
}

std::string Number(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.4g", std::abs(v) < 1e-12 ? 0.0 : v);
  return buffer;
}

bool Finite(double x, double y) { return std::isfinite(x) && std::isfinite(y); }

// Draws an SvgPlot on an SvgCanvas (svg_canvas.h): frame, ticks, labels, series, legend.
class Chart {
 public:
  Chart(const SvgPlot& plot, Range x, Range y)
      : plot_(plot),
        x_(x),
        y_(y),
        w_(FrameWidth(plot)),
        h_(plot.height_px - kTop - kBottom),
        px_{x.lo, x.hi, kLeft, kLeft + w_},
        py_{y.lo, y.hi, kTop + h_, kTop} {}

  void Axes(SvgCanvas& svg) const {
    svg.Rect(kLeft, kTop, w_, h_, "none", "black");
    const double sx = TickStep(x_.Span()), sy = TickStep(y_.Span());
    for (double t = std::ceil(x_.lo / sx) * sx; t <= x_.hi; t += sx) {
      svg.Line(px_(t), kTop + h_, px_(t), kTop + h_ + 5, "black");
      svg.Text(px_(t), kTop + h_ + 20, Number(t), 12, "middle");
    }
    for (double t = std::ceil(y_.lo / sy) * sy; t <= y_.hi; t += sy) {
      svg.Line(kLeft - 5, py_(t), kLeft, py_(t), "black");
      svg.Text(kLeft - 8, py_(t) + 4, Number(t), 12, "end");
    }
    svg.Text(kLeft + w_ / 2, plot_.height_px - 15, plot_.x_label, 12, "middle");
    svg.Text(kLeft, kTop - 8, plot_.y_label, 12, "middle");
    // Centred on the image, not the frame: a wide legend margin would push a long title off.
    svg.Text(plot_.width_px / 2.0, 18, plot_.title, 14, "middle");
  }

  void Series(SvgCanvas& svg, const PlotSeries& s) const {
    std::vector<std::pair<double, double>> points;
    for (size_t i = 0; i < std::min(s.x.size(), s.y.size()); ++i)
      if (Finite(s.x[i], s.y[i])) points.emplace_back(px_(s.x[i]), py_(s.y[i]));
    if (s.dots) {
      for (const auto& [x, y] : points) svg.Circle(x, y, s.width_px, s.color, "none", 0);
    } else if (s.dashed) {
      for (size_t i = 1; i < points.size(); ++i)
        svg.Line(points[i - 1].first, points[i - 1].second, points[i].first, points[i].second,
                 s.color, s.width_px, "6 4");
    } else {
      svg.Polyline(points, s.color, s.width_px);
    }
  }

  void Legend(SvgCanvas& svg) const {
    double y = kTop + 10;
    const double x = kLeft + w_ + 10;
    for (const PlotSeries& s : plot_.series) {
      if (s.label.empty()) continue;
      svg.Line(x, y, x + 20, y, s.color, 3, s.dashed ? "6 4" : "");
      svg.Text(x + 25, y + 4, s.label);
      y += 18;
    }
  }

 private:
  const SvgPlot& plot_;
  Range x_, y_;
  double w_, h_;
  LinearMap px_, py_;
};

}  // namespace

std::string SeriesColor(int k) {
  static const char* const kPalette[] = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e",
                                         "#9467bd", "#8c564b", "#e377c2", "#7f7f7f"};
  return kPalette[((k % 8) + 8) % 8];
}

namespace {

SvgCanvas Draw(const SvgPlot& plot) {
  Range x, y;
  Bounds(plot, &x, &y);
  const double w = FrameWidth(plot), h = plot.height_px - kTop - kBottom;
  if (plot.equal_aspect) EqualAspect(w, h, &x, &y);
  const Chart chart(plot, x, y);
  SvgCanvas svg(plot.width_px, plot.height_px);
  chart.Axes(svg);
  for (const PlotSeries& s : plot.series) chart.Series(svg, s);
  chart.Legend(svg);
  return svg;
}

}  // namespace

std::string RenderSvg(const SvgPlot& plot) { return Draw(plot).Document(); }

bool WriteSvg(const std::string& path, const SvgPlot& plot, std::string* error) {
  return Draw(plot).WriteFile(path, error);
}

}  // namespace demcal::objectives
