#include "outputs/html_report.h"

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "objectives/report/svg_plot.h"
#include "core/io/scratch_dir.h"

using namespace demcal::workflow;

namespace {
int Count(const std::string& text, const std::string& what) {
  int n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}
}  // namespace

TEST_CASE("html report escapes every text it is given", "[unit]") {
  HtmlReport report("a <b> & \"c\"");
  report.Section("<h2>");
  report.Paragraph("<script>alert('x')</script>");
  std::string error;
  REQUIRE(report.Table({.header = {"<th>"}, .rows = {{"a&b"}}}, &error));
  std::string html = report.Document();
  CHECK(html.find("<script>") == std::string::npos);
  CHECK(html.find("&lt;script&gt;alert(&#39;x&#39;)&lt;/script&gt;") != std::string::npos);
  CHECK(html.find("<title>a &lt;b&gt; &amp; &quot;c&quot;</title>") != std::string::npos);
  CHECK(html.find("<td>a&amp;b</td>") != std::string::npos);
}

TEST_CASE("html report sections open and close in balance, synthetic parts carry a badge",
          "[unit]") {
  HtmlReport report("t");
  report.Section("one");
  report.Paragraph("measured");
  report.Section("two", /*synthetic=*/true);
  report.Paragraph("made up", /*synthetic=*/true);
  std::string error;
  REQUIRE(report.Table({.header = {"x"}, .rows = {{"1"}, {"2"}}, .synthetic_rows = {false, true}},
                       &error));
  std::string html = report.Document();
  CHECK(Count(html, "<section>") == 2);
  CHECK(Count(html, "</section>") == 2);
  CHECK(Count(html, "class=\"badge\">synthetic<") == 3);  // section, paragraph, row
  CHECK(Count(html, "<tr class=\"synthetic\">") == 1);
  std::string md = report.Markdown("figures");
  CHECK(Count(md, "**[synthetic]**") == 3);
}

TEST_CASE("html report figures are inline svg without prologue; malformed ones are refused",
          "[unit]") {
  HtmlReport report("t");
  demcal::objectives::SvgPlot plot{.title = "p"};
  plot.series.push_back({.x = {0, 1}, .y = {0, 1}});
  std::string svg = demcal::objectives::RenderSvg(plot);
  std::string error;
  REQUIRE(report.Figure("<?xml version=\"1.0\"?>\n" + svg, "fig", false, &error));
  CHECK(report.Document().find("<?xml") == std::string::npos);
  CHECK(Count(report.Document(), "<svg") == 1);
  CHECK_FALSE(report.Figure("<p>not svg</p>", "bad", false, &error));
  CHECK(error.find("bad") != std::string::npos);
  CHECK_FALSE(report.Figure(svg + "<script></script>", "trailing", false, &error));
  CHECK(report.figure_count() == 1);
}

TEST_CASE("html report refuses a table row narrower than its header", "[unit]") {
  HtmlReport report("t");
  std::string error;
  CHECK_FALSE(report.Table({.caption = "c", .header = {"a", "b"}, .rows = {{"1"}}}, &error));
  CHECK(error.find("row 1 has 1 cells, the header 2") != std::string::npos);
  CHECK_FALSE(report.Table(
      {.header = {"a"}, .rows = {{"1"}}, .synthetic_rows = {true, false}}, &error));
  CHECK(report.table_count() == 0);
}

TEST_CASE("html report writes the page and the markdown with its figure files", "[unit]") {
  namespace fs = std::filesystem;
  const demcal::testing::ScratchDir scratch("html_report_test");
  const fs::path dir = scratch.path();
  HtmlReport report("t");
  demcal::objectives::SvgPlot plot{.title = "p"};
  plot.series.push_back({.x = {0, 1}, .y = {0, 1}});
  std::string error;
  REQUIRE(report.Figure(demcal::objectives::RenderSvg(plot), "first", false, &error));
  REQUIRE(report.Figure(demcal::objectives::RenderSvg(plot), "second", true, &error));
  REQUIRE(report.WriteFile((dir / "report.html").string(), &error));
  REQUIRE(report.WriteMarkdown((dir / "report.md").string(), "figures", &error));
  CHECK(fs::file_size(dir / "report.html") > 100);
  CHECK(fs::exists(dir / "figures" / "figure_01.svg"));
  CHECK(fs::exists(dir / "figures" / "figure_02.svg"));
  std::ifstream md(dir / "report.md");
  std::stringstream text;
  text << md.rdbuf();
  CHECK(text.str().find("](figures/figure_02.svg)") != std::string::npos);
  CHECK_FALSE(report.WriteFile((dir / "missing" / "report.html").string(), &error));
  CHECK(error.find("cannot write") != std::string::npos);
  fs::remove_all(dir);
}

TEST_CASE("html report leads with a headline, marks footnotes and lists each note once",
          "[unit]") {
  HtmlReport report("t");
  report.Section("Verdict");
  report.Headline({{.label = "Matched:", .text = "a <b>", .tone = Tone::kGood},
                   {.label = "Not run:", .text = "c", .notes = {1}, .tone = Tone::kMuted}});
  demcal::objectives::SvgPlot plot{.title = "p"};
  plot.series.push_back({.x = {0, 1}, .y = {0, 1}});
  const std::string svg = demcal::objectives::RenderSvg(plot);
  std::string error;
  REQUIRE(report.FigureRow({{.svg_document = svg, .caption = "one"},
                            {.svg_document = svg, .caption = "two", .synthetic = true}},
                           &error));
  REQUIRE(report.Table({.header = {"q", "verdict"},
                        .rows = {{"a", "within noise"}, {"b", "not run"}, {"c", "not run"}},
                        .row_tones = {Tone::kGood, Tone::kMuted, Tone::kMuted},
                        .tone_column = 1,
                        .row_notes = {{}, {1}, {1}},
                        .note_column = 1},
                       &error));
  report.Footnotes({"the shared note"});
  const std::string html = report.Document();
  CHECK(html.find("<strong>Matched:</strong> a &lt;b&gt;") != std::string::npos);
  CHECK(Count(html, "<li class=\"tone-good\">") == 1);
  CHECK(Count(html, "<td class=\"tone-muted\">not run<sup class=\"note\"><a href=\"#note-1\">1</a>"
                    "</sup></td>") == 2);
  CHECK(Count(html, "<td class=\"tone-good\">within noise</td>") == 1);
  CHECK(Count(html, "the shared note") == 1);
  CHECK(Count(html, "<li id=\"note-1\">") == 1);
  CHECK(Count(html, "<div class=\"figure-row\">") == 1);
  CHECK(report.figure_count() == 2);
  // The verdict reads first: headline, then the figures, then the table, then its notes.
  const size_t headline = html.find("class=\"headline\""), figures = html.find("figure-row\">");
  const size_t table = html.find("<table>"), notes = html.find("<ol class=\"notes\">");
  CHECK(headline < figures);
  CHECK(figures < table);
  CHECK(table < notes);
  // The Markdown twin keeps the same order, with "[k]" marks and a numbered list.
  const std::string md = report.Markdown("figures");
  CHECK(md.find("- **Not run:** c [1]") != std::string::npos);
  CHECK(Count(md, "| not run [1] |") == 2);
  CHECK(Count(md, "the shared note") == 1);
  CHECK(md.find("- **Matched:**") < md.find("![Figure 1](figures/figure_01.svg)"));
  CHECK(md.find("![Figure 2](figures/figure_02.svg)") < md.find("| q | verdict |"));
  CHECK(md.find("| q | verdict |") < md.find("1. the shared note"));
}

TEST_CASE("html report page fills the window: no fixed narrow column", "[unit]") {
  const std::string html = HtmlReport("t").Document();
  const size_t from = html.find("<style>"), to = html.find("</style>");
  REQUIRE(to != std::string::npos);
  const std::string style = html.substr(from, to - from);
  const size_t body_at = style.find("body{");
  REQUIRE(body_at != std::string::npos);
  const std::string body = style.substr(body_at, style.find('}', body_at) - body_at);
  CHECK(body.find("max-width") == std::string::npos);
  CHECK(style.find("table{border-collapse:collapse;width:100%}") != std::string::npos);
  CHECK(style.find("overflow-x:auto") != std::string::npos);  // wide tables scroll in their box
}

TEST_CASE("html report refuses footnote and tone lists that do not fit the table", "[unit]") {
  HtmlReport report("t");
  std::string error;
  CHECK_FALSE(report.Table({.header = {"a"}, .rows = {{"1"}}, .row_notes = {{1}, {2}}}, &error));
  CHECK(error.find("row_notes has 2 entries for 1 rows") != std::string::npos);
  CHECK_FALSE(report.Table({.header = {"a"}, .rows = {{"1"}}, .row_notes = {{0}}}, &error));
  CHECK(error.find("footnote number 0") != std::string::npos);
  CHECK_FALSE(report.Table(
      {.header = {"a"}, .rows = {{"1"}}, .row_tones = {Tone::kGood}, .tone_column = 1}, &error));
  CHECK(error.find("tone_column") != std::string::npos);
  CHECK_FALSE(report.FigureRow({{.svg_document = "<p>no</p>", .caption = "bad"}}, &error));
  CHECK(report.table_count() == 0);
  CHECK(report.figure_count() == 0);
}
