// html_report_sample OUT.html: writes a report with every kind of block HtmlReport has (a
// headline, sections, synthetic badges, escaped text, a wide table with coloured verdicts and
// footnote marks, its footnotes, a row of figures and single figures from SvgPlot), for the
// browser test (html_report_browser_test.sh, scripts/check_html_report.py).
#include <iostream>
#include <string>

#include "objectives/report/svg_plot.h"
#include "outputs/html_report.h"

int main(int argc, char** argv) {
  using demcal::workflow::HtmlReport;
  using demcal::workflow::Tone;
  if (argc != 2) {
    std::cerr << "usage: html_report_sample OUT.html\n";
    return 2;
  }
  HtmlReport report("Sample report <&> \"quotes\"");
  report.Section("Verdict");
  report.Headline({{.label = "Matched:", .text = "1 of 2 compared: angle", .tone = Tone::kGood},
                   {.label = "Did not match:", .text = "1 of 2: Γ", .tone = Tone::kBad},
                   {.label = "Not run:", .text = "count", .notes = {1}, .tone = Tone::kMuted}});
  report.Section("Data");
  report.Paragraph("Text with markup characters: <script>alert('x')</script> & more.");
  report.List({"first item", "second <item>"});
  report.Code("demcal reproduce alizadeh2018 --out runs/main --quick");
  std::string error;
  bool ok = report.Table({.caption = "A table",
                          .header = {"w [wt%]", "angle [deg]", "verdict", "source"},
                          .rows = {{"0", "31.0", "within noise", "Table 1"},
                                   {"1.5", "39.2", "differs by 2 deg (2 σ)", "Fig. 6"},
                                   {"2.5", "–", "not run", "Fig. 6"}},
                          .synthetic_rows = {false, true, false},
                          .row_tones = {Tone::kGood, Tone::kBad, Tone::kMuted},
                          .tone_column = 2,
                          .row_notes = {{}, {2}, {1}},
                          .note_column = 2},
                         &error);
  report.Footnotes({"a long note shared by rows, printed once", "why it differs"});
  report.Section("Figures", /*synthetic=*/true);
  demcal::objectives::SvgPlot plot{.title = "line", .x_label = "x [-]", .y_label = "y [-]"};
  plot.series.push_back({.label = "y = x²", .x = {0, 1, 2, 3}, .y = {0, 1, 4, 9}, .dots = true});
  ok = ok && report.FigureRow({{.svg_document = demcal::objectives::RenderSvg(plot),
                                .caption = "left of a row"},
                               {.svg_document = demcal::objectives::RenderSvg(plot),
                                .caption = "right of a row", .synthetic = true}},
                              &error);
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
