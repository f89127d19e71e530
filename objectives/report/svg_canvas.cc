#include "objectives/report/svg_canvas.h"

#include <cstdio>

#include "objectives/report/text_file.h"

namespace demcal::objectives {
namespace {

// Pixels with 0.01 px resolution: plenty for a picture, keeps files small.
std::string Px(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f", v);
  return buf;
}

std::string Escape(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '&':
        out += "&amp;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

std::string Paint(const std::string& fill, const std::string& stroke, double stroke_width) {
  return " fill=\"" + Escape(fill) + "\" stroke=\"" + Escape(stroke) + "\" stroke-width=\"" +
         Px(stroke_width) + "\"";
}

}  // namespace

SvgCanvas::SvgCanvas(double width_px, double height_px)
    : width_px_(width_px), height_px_(height_px) {}

void SvgCanvas::Circle(double cx, double cy, double r, const std::string& fill,
                       const std::string& stroke, double stroke_width) {
  body_ += "<circle cx=\"" + Px(cx) + "\" cy=\"" + Px(cy) + "\" r=\"" + Px(r) + "\"" +
           Paint(fill, stroke, stroke_width) + "/>\n";
}

void SvgCanvas::Rect(double x, double y, double w, double h, const std::string& fill,
                     const std::string& stroke, double stroke_width) {
  body_ += "<rect x=\"" + Px(x) + "\" y=\"" + Px(y) + "\" width=\"" + Px(w) + "\" height=\"" +
           Px(h) + "\"" + Paint(fill, stroke, stroke_width) + "/>\n";
}

void SvgCanvas::Line(double x1, double y1, double x2, double y2, const std::string& stroke,
                     double stroke_width, const std::string& dash) {
  body_ += "<line x1=\"" + Px(x1) + "\" y1=\"" + Px(y1) + "\" x2=\"" + Px(x2) + "\" y2=\"" +
           Px(y2) + "\"" + Paint("none", stroke, stroke_width);
  if (!dash.empty()) body_ += " stroke-dasharray=\"" + Escape(dash) + "\"";
  body_ += "/>\n";
}

void SvgCanvas::Polyline(const std::vector<std::pair<double, double>>& points,
                         const std::string& stroke, double stroke_width) {
  body_ += "<polyline points=\"";
  for (const auto& [x, y] : points) body_ += Px(x) + "," + Px(y) + " ";
  body_ += '"';  // built in steps: GCC 12 gives a false -Wrestrict on "literal" + string&&
  body_ += Paint("none", stroke, stroke_width);
  body_ += "/>\n";
}

void SvgCanvas::Polygon(const std::vector<std::pair<double, double>>& points,
                        const std::string& fill, double opacity) {
  body_ += "<polygon points=\"";
  for (const auto& [x, y] : points) body_ += Px(x) + "," + Px(y) + " ";
  body_ += '"';
  body_ += Paint(fill, "none", 0);
  body_ += " fill-opacity=\"" + Px(opacity) + "\"/>\n";
}

void SvgCanvas::Text(double x, double y, const std::string& text, double size_px,
                     const std::string& anchor) {
  body_ += "<text x=\"" + Px(x) + "\" y=\"" + Px(y) + "\" font-family=\"sans-serif\" font-size=\"" +
           Px(size_px) + "\" text-anchor=\"" + Escape(anchor) + "\">" + Escape(text) + "</text>\n";
}

std::string SvgCanvas::Document() const {
  return "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + Px(width_px_) + "\" height=\"" +
         Px(height_px_) + "\" viewBox=\"0 0 " + Px(width_px_) + " " + Px(height_px_) + "\">\n" +
         "<rect x=\"0\" y=\"0\" width=\"100%\" height=\"100%\" fill=\"white\"/>\n" + body_ +
         "</svg>\n";
}

bool SvgCanvas::WriteFile(const std::string& path, std::string* error) const {
  return WriteTextFile(path, [this](std::ostream& out) { out << Document(); }, error);
}

}  // namespace demcal::objectives
