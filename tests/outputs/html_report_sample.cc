// html_report_sample OUT.html: writes a report with every kind of block HtmlReport has (sections,
// synthetic badges, escaped text, a table, inline SVG figures from SvgPlot), for the browser test
// (html_report_browser_test.sh, scripts/check_html_report.py).
#include <iostream>
#include <string>

#include "objectives/report/svg_plot.h"
#include "outputs/html_report.h"

int main(int argc, char** argv) {
  using demcal::workflow::HtmlReport;
  if (argc != 2) {
    std::cerr << "usage: html_report_sample OUT.html\n";
    return 2;
  }
  HtmlReport report("Sample report <&> \"quotes\"");
  report.Section("Data");
  report.Paragraph("Text with markup characters: <script>alert('x')</script> & more.");
  report.List({"first item", "second <item>"});
  report.Code("demcal reproduce alizadeh2018 --out runs/main --quick");
  std::string error;
  bool ok = report.Table({.caption = "A table",
                          .header = {"w [wt%]", "angle [deg]"},
                          .rows = {{"0", "31.0"}, {"1.5", "39.2"}},
                          .synthetic_rows = {false, true}},
                         &error);
  report.Section("Figures", /*synthetic=*/true);
  demcal::objectives::SvgPlot plot{.title = "line", .x_label = "x [-]", .y_label = "y [-]"};
  plot.series.push_back({.label = "y = x²", .x = {0, 1, 2, 3}, .y = {0, 1, 4, 9}, .dots = true});
  ok = ok && report.Figure(demcal::objectives::RenderSvg(plot), "a plot", true, &error);
  ok = ok && report.Figure("<?xml version=\"1.0\"?>\n" + demcal::objectives::RenderSvg(plot),
                           "the same plot, with an XML prologue", false, &error);
  ok = ok && report.WriteFile(argv[1], &error);
  if (!ok) {
    std::cerr << error << "\n";
    return 1;
  }
  return 0;
}
