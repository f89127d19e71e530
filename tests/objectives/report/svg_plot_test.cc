#include "objectives/report/svg_plot.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <numbers>
#include <regex>
#include <sstream>

#include "objectives/report/discharge_svg.h"
#include "objectives/report/heap_profile_svg.h"
#include "objectives/metrics/sloped_heaps.h"

using namespace demcal::objectives;

namespace {

int Count(const std::string& text, const std::string& what) {
  int n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

// The pixel coordinates of the first polyline.
std::vector<double> FirstPolyline(const std::string& svg) {
  std::smatch m;
  REQUIRE(std::regex_search(svg, m, std::regex("points=\"([^\"]*)\"")));
  std::string numbers = m[1];
  for (char& c : numbers)
    if (c == ',') c = ' ';
  std::istringstream in(numbers);
  std::vector<double> v;
  for (double x; in >> x;) v.push_back(x);
  return v;
}

}  // namespace

TEST_CASE("svg plot: lines, dots, escaped text, skipped non-finite points", "[unit]") {
  SvgPlot plot{.title = "a < b & c", .x_label = "x [m]", .y_label = "y [m]"};
  plot.series.push_back({.label = "line", .x = {0, 1, 2}, .y = {0, 1, NAN}});
  plot.series.push_back({.label = "", .x = {0, 1}, .y = {1, 0}, .dots = true});
  const std::string svg = RenderSvg(plot);
  CHECK(svg.rfind("<svg xmlns=\"http://www.w3.org/2000/svg\"", 0) == 0);
  CHECK(svg.find("</svg>") != std::string::npos);
  CHECK(svg.find("a &lt; b &amp; c") != std::string::npos);
  CHECK(Count(svg, "<polyline") == 1);
  CHECK(Count(svg, "<circle") == 2);
  CHECK(FirstPolyline(svg).size() == 4);  // two finite points of the line, x and y each
  CHECK(svg.find("nan") == std::string::npos);
}

TEST_CASE("svg plot: equal aspect draws a 1:1 slope at 45 degrees", "[unit]") {
  SvgPlot plot{.equal_aspect = true, .width_px = 900, .height_px = 300};
  plot.series.push_back({.x = {0, 1}, .y = {0, 1}});
  const std::vector<double> p = FirstPolyline(RenderSvg(plot));
  REQUIRE(p.size() == 4);
  // Screen y grows downwards; coordinates are written to 0.01 px.
  CHECK(p[2] - p[0] == Approx(p[1] - p[3]).margin(0.011));
  CHECK(p[2] - p[0] > 10);
}

TEST_CASE("svg plot: written to a file, an unwritable path is refused", "[unit]") {
  const std::string path = "svg_plot_test_output.svg";
  std::string error;
  SvgPlot plot;
  plot.series.push_back({.x = {0, 1}, .y = {2, 3}});
  REQUIRE(WriteSvg(path, plot, &error));
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  CHECK(text.str() == RenderSvg(plot));
  std::remove(path.c_str());
  CHECK_FALSE(WriteSvg("/nonexistent-dir/x.svg", plot, &error));
  CHECK(error.find("/nonexistent-dir/x.svg") != std::string::npos);
}

TEST_CASE("heap profile plot: surface dots, window lines and one line per flank", "[unit]") {
  const Snapshot heap = testing::SlotHeap({.left_deg = 30, .right_deg = 40}, 0.002, {});
  const ReposeAngle angle = MeasureSlotHeapAngle(heap, {});
  REQUIRE(angle.ok);
  const SvgPlot plot = SlotHeapProfilePlot(heap, angle, {});
  REQUIRE(plot.series.size() == 1 + 2 + 2);
  CHECK(plot.series[0].dots);
  const PlotSeries& left = plot.series[3];
  CHECK(left.label == "left 30.0°");
  // The left line rises towards the apex at 30°, drawn in mm.
  const double rise = (left.y[0] - left.y[1]) / (left.x[1] - left.x[0]);
  CHECK(rise == Approx(-std::tan(30 * std::numbers::pi / 180)).epsilon(1e-6));
  CHECK(left.x[0] <= angle.apex_s_m * 1e3);
  const Snapshot cone = testing::ConicalHeap(0, 0, 0.03, 35, 0.002, {});
  const ReposeAngle cone_angle = MeasureConicalHeapAngle(cone, {0, 0, 0}, {.sectors = 6});
  REQUIRE(cone_angle.ok);
  CHECK(ConicalHeapProfilePlot(cone, {0, 0, 0}, cone_angle, {.sectors = 6}).series.size() ==
        1 + 2 + 6);
}

TEST_CASE("discharge plots: mass with the fit, composition as steps", "[unit]") {
  const std::vector<OutflowSample> samples = {{0, {0, 0}},     {1, {0.9, 0.1}}, {2, {1.8, 0.2}},
                                              {3, {2.7, 0.3}}, {4, {3.6, 0.4}}, {5, {3.6, 0.4}}};
  const DischargeMetrics m = AnalyseDischarge(samples, 0, {.composition_bins = 4});
  REQUIRE(m.ok);
  const SvgPlot mass = DischargeMassPlot(samples, 0, m, {"big"});
  REQUIRE(mass.series.size() == 1 + 2 + 1);
  CHECK(mass.series[0].y.back() == Approx(4000));  // g
  CHECK(mass.series[2].label == "species 1");
  CHECK(mass.series[3].dashed);
  const SvgPlot composition = DischargeCompositionPlot(m, 0, {"big", "small"});
  REQUIRE(composition.series.size() == 2);
  CHECK(composition.series[1].y.size() == 2 * 4);
  for (double f : composition.series[1].y) CHECK(f == Approx(0.1));
}

TEST_CASE("svg plot: a long legend label gets the room it needs", "[unit]") {
  // Reproduce's Fig. 7 style plot cut "demcal at calibrated Γ ± sem" at the image's right edge.
  // The label must end inside the image at 7 px per character (12 px sans-serif averages less).
  const std::string label = "demcal at calibrated Γ ± sem, a longer label";
  SvgPlot plot{.title = "t", .x_label = "x", .y_label = "y"};
  plot.series.push_back({.label = label, .x = {0, 1}, .y = {0, 1}});
  const std::string svg = RenderSvg(plot);
  std::smatch m;
  REQUIRE(std::regex_search(svg, m, std::regex("<text x=\"([0-9.]+)\"[^>]*>demcal at")));
  const double start_px = std::stod(m[1]);
  const double characters = 44;  // the label's code points (Γ and ± are one each)
  CHECK(start_px + 7 * characters <= plot.width_px);
  // A short label keeps the usual plot area (frame 490 px wide in a 720 px image).
  SvgPlot short_label = plot;
  short_label.series[0].label = "data";
  CHECK(RenderSvg(short_label).find("width=\"490.00\"") != std::string::npos);
}
