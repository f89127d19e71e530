#include "objectives/svg_plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace demcal::objectives {

namespace {

constexpr double kLeft = 80, kRight = 150, kTop = 40, kBottom = 60;  // margins, px

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

std::string Escape(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '&')
      out += "&amp;";
    else if (c == '<')
      out += "&lt;";
    else if (c == '>')
      out += "&gt;";
    else
      out += c;
  }
  return out;
}

std::string Number(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.4g", std::abs(v) < 1e-12 ? 0.0 : v);
  return buffer;
}

class Canvas {
 public:
  Canvas(const SvgPlot& plot, Range x, Range y) : plot_(plot), x_(x), y_(y) {
    w_ = plot.width_px - kLeft - kRight;
    h_ = plot.height_px - kTop - kBottom;
  }
  double Px(double x) const { return kLeft + (x - x_.lo) / x_.Span() * w_; }
  double Py(double y) const { return kTop + (y_.hi - y) / y_.Span() * h_; }

  void Axes(std::ostringstream& out) const {
    out << "<rect x='" << kLeft << "' y='" << kTop << "' width='" << w_ << "' height='" << h_
        << "' fill='none' stroke='black'/>\n";
    const double sx = TickStep(x_.Span()), sy = TickStep(y_.Span());
    for (double t = std::ceil(x_.lo / sx) * sx; t <= x_.hi; t += sx)
      out << "<line x1='" << Px(t) << "' y1='" << kTop + h_ << "' x2='" << Px(t) << "' y2='"
          << kTop + h_ + 5 << "' stroke='black'/><text x='" << Px(t) << "' y='" << kTop + h_ + 20
          << "' text-anchor='middle'>" << Number(t) << "</text>\n";
    for (double t = std::ceil(y_.lo / sy) * sy; t <= y_.hi; t += sy)
      out << "<line x1='" << kLeft - 5 << "' y1='" << Py(t) << "' x2='" << kLeft << "' y2='"
          << Py(t) << "' stroke='black'/><text x='" << kLeft - 8 << "' y='" << Py(t) + 4
          << "' text-anchor='end'>" << Number(t) << "</text>\n";
    out << "<text x='" << kLeft + w_ / 2 << "' y='" << plot_.height_px - 15
        << "' text-anchor='middle'>" << Escape(plot_.x_label) << "</text>\n"
        << "<text transform='translate(20," << kTop + h_ / 2
        << ") rotate(-90)' text-anchor='middle'>" << Escape(plot_.y_label) << "</text>\n"
        << "<text x='" << kLeft + w_ / 2 << "' y='25' text-anchor='middle' font-weight='bold'>"
        << Escape(plot_.title) << "</text>\n";
  }

  void Series(std::ostringstream& out, const PlotSeries& s) const {
    const size_t n = std::min(s.x.size(), s.y.size());
    if (s.dots) {
      for (size_t i = 0; i < n; ++i)
        if (std::isfinite(s.x[i]) && std::isfinite(s.y[i]))
          out << "<circle cx='" << Px(s.x[i]) << "' cy='" << Py(s.y[i]) << "' r='" << s.width_px
              << "' fill='" << s.color << "'/>\n";
      return;
    }
    out << "<polyline fill='none' stroke='" << s.color << "' stroke-width='" << s.width_px << "'"
        << (s.dashed ? " stroke-dasharray='6 4'" : "") << " points='";
    for (size_t i = 0; i < n; ++i)
      if (std::isfinite(s.x[i]) && std::isfinite(s.y[i]))
        out << Px(s.x[i]) << ',' << Py(s.y[i]) << ' ';
    out << "'/>\n";
  }

  void Legend(std::ostringstream& out) const {
    double y = kTop + 10;
    for (const PlotSeries& s : plot_.series) {
      if (s.label.empty()) continue;
      const double x = kLeft + w_ + 10;
      out << "<line x1='" << x << "' y1='" << y << "' x2='" << x + 20 << "' y2='" << y
          << "' stroke='" << s.color << "' stroke-width='3'/><text x='" << x + 25 << "' y='"
          << y + 4 << "'>" << Escape(s.label) << "</text>\n";
      y += 18;
    }
  }

 private:
  const SvgPlot& plot_;
  Range x_, y_;
  double w_ = 0, h_ = 0;
};

}  // namespace

std::string SeriesColor(int k) {
  static const char* const kPalette[] = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e",
                                         "#9467bd", "#8c564b", "#e377c2", "#7f7f7f"};
  return kPalette[((k % 8) + 8) % 8];
}

std::string RenderSvg(const SvgPlot& plot) {
  Range x, y;
  Bounds(plot, &x, &y);
  const double w = plot.width_px - kLeft - kRight, h = plot.height_px - kTop - kBottom;
  if (plot.equal_aspect) EqualAspect(w, h, &x, &y);
  const Canvas canvas(plot, x, y);
  std::ostringstream out;
  out << std::fixed << std::setprecision(2);  // pixels; tick labels are formatted apart
  out << "<svg xmlns='http://www.w3.org/2000/svg' width='" << plot.width_px << "' height='"
      << plot.height_px << "' font-family='sans-serif' font-size='12'>\n"
      << "<rect width='100%' height='100%' fill='white'/>\n";
  canvas.Axes(out);
  for (const PlotSeries& s : plot.series) canvas.Series(out, s);
  canvas.Legend(out);
  out << "</svg>\n";
  return out.str();
}

bool WriteSvg(const std::string& path, const SvgPlot& plot, std::string* error) {
  std::ofstream file(path);
  if (file) file << RenderSvg(plot);
  if (!file) {
    if (error) *error = "cannot write " + path;
    return false;
  }
  return true;
}

}  // namespace demcal::objectives
