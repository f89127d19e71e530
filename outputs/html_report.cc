#include "outputs/html_report.h"

#include <cctype>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <utility>

#include "core/io/atomic_file.h"

namespace demcal::workflow {
namespace {

constexpr const char* kStyle = R"(body{font-family:sans-serif;max-width:60em;margin:1em auto;
padding:0 1em;color:#222;line-height:1.45}
h1{border-bottom:2px solid #444}h2{border-bottom:1px solid #bbb;margin-top:2em}
table{border-collapse:collapse;margin:1em 0}caption{font-weight:bold;text-align:left;padding:.3em 0}
th,td{border:1px solid #bbb;padding:.25em .6em;text-align:left;vertical-align:top}
th{background:#eee}tr.synthetic td{background:#fff6e0}
figure{margin:1.5em 0}figure svg{max-width:100%;height:auto;border:1px solid #ddd}
figcaption{font-size:.9em;color:#444}pre{background:#f4f4f4;padding:.6em;overflow-x:auto}
.badge{display:inline-block;font-size:.75em;font-weight:bold;color:#8a4b00;background:#ffe2b0;
border:1px solid #d08a2a;border-radius:.3em;padding:0 .4em;margin-left:.4em;vertical-align:middle}
)";

constexpr const char* kBadge = "<span class=\"badge\">synthetic</span>";

std::string Badge(bool synthetic) { return synthetic ? kBadge : ""; }

// The <svg ...>...</svg> element of `document` (leading XML prologue, comments and whitespace
// dropped); empty if there is none or anything but whitespace follows it.
std::string SvgElement(const std::string& document) {
  size_t start = document.find("<svg");
  size_t end = document.rfind("</svg>");
  if (start == std::string::npos || end == std::string::npos || end < start) return "";
  for (size_t i = end + 6; i < document.size(); ++i) {
    if (!std::isspace(static_cast<unsigned char>(document[i]))) return "";
  }
  std::string before = document.substr(0, start);
  size_t prologue = before.find("?>");
  std::string rest = prologue == std::string::npos ? before : before.substr(prologue + 2);
  for (char c : rest) {
    if (!std::isspace(static_cast<unsigned char>(c))) return "";
  }
  return document.substr(start, end + 6 - start);
}

std::string MarkdownCell(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '|') out += "\\|";
    else if (c == '\n') out += ' ';
    else out += c;
  }
  return out;
}

void HtmlTableBody(const HtmlTable& table, std::string* out) {
  *out += "<table>\n";
  if (!table.caption.empty()) *out += "<caption>" + HtmlEscape(table.caption) + "</caption>\n";
  *out += "<thead><tr>";
  for (const auto& h : table.header) *out += "<th>" + HtmlEscape(h) + "</th>";
  *out += "</tr></thead>\n<tbody>\n";
  for (size_t r = 0; r < table.rows.size(); ++r) {
    bool synthetic = !table.synthetic_rows.empty() && table.synthetic_rows[r];
    *out += synthetic ? "<tr class=\"synthetic\">" : "<tr>";
    for (size_t c = 0; c < table.rows[r].size(); ++c) {
      *out += "<td>" + HtmlEscape(table.rows[r][c]) + (c == 0 ? Badge(synthetic) : "") + "</td>";
    }
    *out += "</tr>\n";
  }
  *out += "</tbody>\n</table>\n";
}

void MarkdownTableBody(const HtmlTable& table, std::string* out) {
  if (!table.caption.empty()) *out += "**" + MarkdownCell(table.caption) + "**\n\n";
  *out += "|";
  for (const auto& h : table.header) *out += " " + MarkdownCell(h) + " |";
  *out += "\n|";
  for (size_t c = 0; c < table.header.size(); ++c) *out += " --- |";
  *out += "\n";
  for (size_t r = 0; r < table.rows.size(); ++r) {
    bool synthetic = !table.synthetic_rows.empty() && table.synthetic_rows[r];
    *out += "|";
    for (size_t c = 0; c < table.rows[r].size(); ++c) {
      *out += " " + MarkdownCell(table.rows[r][c]) +
              (c == 0 && synthetic ? " **[synthetic]**" : "") + " |";
    }
    *out += "\n";
  }
  *out += "\n";
}

}  // namespace

std::string HtmlEscape(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      default: out += c;
    }
  }
  return out;
}

HtmlReport::HtmlReport(std::string title) : title_(std::move(title)) {}

void HtmlReport::Section(const std::string& heading, bool synthetic) {
  blocks_.push_back({.kind = Kind::kSection, .text = heading, .synthetic = synthetic});
}

void HtmlReport::Subheading(const std::string& heading) {
  blocks_.push_back({.kind = Kind::kSubheading, .text = heading});
}

void HtmlReport::Paragraph(const std::string& text, bool synthetic) {
  blocks_.push_back({.kind = Kind::kParagraph, .text = text, .synthetic = synthetic});
}

void HtmlReport::List(const std::vector<std::string>& items) {
  blocks_.push_back({.kind = Kind::kList, .items = items});
}

void HtmlReport::Code(const std::string& text) {
  blocks_.push_back({.kind = Kind::kCode, .text = text});
}

bool HtmlReport::Table(const HtmlTable& table, std::string* error) {
  if (!table.synthetic_rows.empty() && table.synthetic_rows.size() != table.rows.size()) {
    if (error) *error = "table '" + table.caption + "': synthetic_rows has " +
                        std::to_string(table.synthetic_rows.size()) + " flags for " +
                        std::to_string(table.rows.size()) + " rows";
    return false;
  }
  for (size_t r = 0; r < table.rows.size(); ++r) {
    if (table.rows[r].size() != table.header.size()) {
      if (error) *error = "table '" + table.caption + "': row " + std::to_string(r + 1) + " has " +
                          std::to_string(table.rows[r].size()) + " cells, the header " +
                          std::to_string(table.header.size());
      return false;
    }
  }
  blocks_.push_back({.kind = Kind::kTable, .table = table});
  ++table_count_;
  return true;
}

bool HtmlReport::Figure(const std::string& svg_document, const std::string& caption,
                        bool synthetic, std::string* error) {
  std::string svg = SvgElement(svg_document);
  if (svg.empty()) {
    if (error) *error = "figure '" + caption + "': not a single <svg>...</svg> element";
    return false;
  }
  blocks_.push_back(
      {.kind = Kind::kFigure, .text = caption, .svg = std::move(svg), .synthetic = synthetic});
  ++figure_count_;
  return true;
}

std::string HtmlReport::Document() const {
  std::string out = "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n";
  out += "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n";
  out += "<title>" + HtmlEscape(title_) + "</title>\n<style>\n" + kStyle + "</style>\n";
  out += "</head>\n<body>\n<h1>" + HtmlEscape(title_) + "</h1>\n";
  bool section_open = false;
  int figure = 0;
  for (const Block& b : blocks_) {
    switch (b.kind) {
      case Kind::kSection:
        if (section_open) out += "</section>\n";
        out += "<section>\n<h2>" + HtmlEscape(b.text) + Badge(b.synthetic) + "</h2>\n";
        section_open = true;
        break;
      case Kind::kSubheading: out += "<h3>" + HtmlEscape(b.text) + "</h3>\n"; break;
      case Kind::kParagraph:
        out += "<p>" + Badge(b.synthetic) + (b.synthetic ? " " : "") + HtmlEscape(b.text) +
               "</p>\n";
        break;
      case Kind::kList:
        out += "<ul>\n";
        for (const auto& item : b.items) out += "<li>" + HtmlEscape(item) + "</li>\n";
        out += "</ul>\n";
        break;
      case Kind::kCode: out += "<pre>" + HtmlEscape(b.text) + "</pre>\n"; break;
      case Kind::kTable: HtmlTableBody(b.table, &out); break;
      case Kind::kFigure:
        ++figure;
        out += "<figure id=\"figure-" + std::to_string(figure) + "\">\n" + b.svg +
               "\n<figcaption>Figure " + std::to_string(figure) + ". " + HtmlEscape(b.text) +
               Badge(b.synthetic) + "</figcaption>\n</figure>\n";
        break;
    }
  }
  if (section_open) out += "</section>\n";
  out += "</body>\n</html>\n";
  return out;
}

std::string HtmlReport::FigureFileName(int k) {
  char name[32];
  std::snprintf(name, sizeof(name), "figure_%02d.svg", k + 1);
  return name;
}

std::string HtmlReport::Markdown(const std::string& figure_dir) const {
  std::string out = "# " + title_ + "\n\n";
  int figure = 0;
  for (const Block& b : blocks_) {
    const std::string tag = b.synthetic ? " **[synthetic]**" : "";
    switch (b.kind) {
      case Kind::kSection: out += "## " + b.text + tag + "\n\n"; break;
      case Kind::kSubheading: out += "### " + b.text + "\n\n"; break;
      case Kind::kParagraph: out += (b.synthetic ? "**[synthetic]** " : "") + b.text + "\n\n"; break;
      case Kind::kList:
        for (const auto& item : b.items) out += "- " + item + "\n";
        out += "\n";
        break;
      case Kind::kCode: out += "```\n" + b.text + "\n```\n\n"; break;
      case Kind::kTable: MarkdownTableBody(b.table, &out); break;
      case Kind::kFigure:
        out += "![Figure " + std::to_string(figure + 1) + "](" + figure_dir + "/" +
               FigureFileName(figure) + ")\n\n*Figure " + std::to_string(figure + 1) + ". " +
               b.text + "*" + tag + "\n\n";
        ++figure;
        break;
    }
  }
  return out;
}

bool HtmlReport::WriteFile(const std::string& path, std::string* error) const {
  return core::io::WriteFileAtomically(path, [this](std::ostream& out) { out << Document(); },
                                       error);
}

bool HtmlReport::WriteMarkdown(const std::string& md_path, const std::string& figure_dir,
                               std::string* error) const {
  namespace fs = std::filesystem;
  fs::path dir = fs::path(md_path).parent_path() / figure_dir;
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) {
    if (error) *error = "cannot create '" + dir.string() + "': " + ec.message();
    return false;
  }
  int k = 0;
  for (const Block& b : blocks_) {
    if (b.kind != Kind::kFigure) continue;
    std::string path = (dir / FigureFileName(k++)).string();
    const std::string& svg = b.svg;
    if (!core::io::WriteFileAtomically(path, [&svg](std::ostream& out) { out << svg << "\n"; },
                                       error)) {
      return false;
    }
  }
  std::string md = Markdown(figure_dir);
  return core::io::WriteFileAtomically(md_path, [&md](std::ostream& out) { out << md; }, error);
}

}  // namespace demcal::workflow
