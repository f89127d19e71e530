#pragma once
// SvgCanvas: a minimal hand-written SVG document (no dependencies) for the heap pictures and
// plots. Coordinates are SVG pixels (origin top left, y down); LinearMap turns data or metres into
// pixels. Not thread-safe (build one per picture). Usage:
//   SvgCanvas svg(800, 400);
//   svg.Circle(10, 10, 3, "#d62728", "none");
//   if (!svg.WriteFile("heap.svg", &error)) ...
#include <string>
#include <utility>
#include <vector>

namespace demcal::objectives {

// Maps [from_lo, from_hi] linearly onto [to_lo, to_hi] (to_hi < to_lo flips the axis).
struct LinearMap {
  double from_lo = 0, from_hi = 1, to_lo = 0, to_hi = 1;
  double operator()(double v) const {
    return to_lo + (v - from_lo) / (from_hi - from_lo) * (to_hi - to_lo);
  }
};

class SvgCanvas {
 public:
  SvgCanvas(double width_px, double height_px);

  void Circle(double cx, double cy, double r, const std::string& fill, const std::string& stroke,
              double stroke_width = 0.5);
  void Rect(double x, double y, double w, double h, const std::string& fill,
            const std::string& stroke, double stroke_width = 1);
  void Line(double x1, double y1, double x2, double y2, const std::string& stroke,
            double stroke_width = 1, const std::string& dash = "");
  void Polyline(const std::vector<std::pair<double, double>>& points, const std::string& stroke,
                double stroke_width = 1.5);
  // A closed filled shape without outline; opacity in (0, 1] (e.g. a translucent band).
  void Polygon(const std::vector<std::pair<double, double>>& points, const std::string& fill,
               double opacity);
  // Text is XML-escaped; anchor is "start", "middle" or "end".
  void Text(double x, double y, const std::string& text, double size_px = 12,
            const std::string& anchor = "start");

  std::string Document() const;
  bool WriteFile(const std::string& path, std::string* error) const;

 private:
  double width_px_, height_px_;
  std::string body_;
};

}  // namespace demcal::objectives
