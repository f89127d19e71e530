#include "outputs/html_report.h"

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "objectives/report/svg_plot.h"

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
  fs::path dir = fs::temp_directory_path() / "demcal_html_report_test";
  fs::remove_all(dir);
  fs::create_directories(dir);
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
