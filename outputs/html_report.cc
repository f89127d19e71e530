#include "outputs/html_report.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <sstream>
#include <utility>

#include "core/io/atomic_file.h"

namespace demcal::workflow {
namespace {

// The page fills the window (tables and figure rows use the whole width); running text keeps a
// readable line length; a table wider than a narrow window scrolls inside its own box.
constexpr const char* kStyle = R"(*{box-sizing:border-box}
body{font-family:system-ui,-apple-system,"Segoe UI",sans-serif;margin:0;padding:.5em 2.5vw 3em;
color:#222;line-height:1.45}
p,ul,ol,pre{max-width:80em}
h1{border-bottom:2px solid #444;margin:.4em 0 .6em}h2{border-bottom:1px solid #bbb;margin-top:2em}
.table-wrap{overflow-x:auto;margin:1em 0}
table{border-collapse:collapse;width:100%}caption{font-weight:bold;text-align:left;padding:.3em 0}
th,td{border:1px solid #bbb;padding:.3em .6em;text-align:left;vertical-align:top}
th{background:#eee}tr.synthetic td{background:#fff6e0}
td.tone-good{color:#11632c;font-weight:600}td.tone-bad{color:#a3111a;font-weight:600}
td.tone-muted{color:#666}
sup.note{font-size:.75em;margin-left:.15em}sup.note a{text-decoration:none}
figure{margin:1.5em 0}figure svg{max-width:100%;height:auto;border:1px solid #ddd}
.figure-row{display:grid;grid-template-columns:repeat(auto-fit,minmax(min(100%,36em),1fr));
gap:1em 1.5em;margin:1em 0}
.figure-row figure{margin:0}.figure-row figure svg{width:100%}
figcaption{font-size:.9em;color:#444}pre{background:#f4f4f4;padding:.6em;overflow-x:auto}
ul.headline{list-style:none;padding:.6em 1em;margin:1em 0;background:#f5f7fa;max-width:none;
border:1px solid #d5dbe3;border-radius:.4em;font-size:1.05em}
ul.headline li{margin:.3em 0;padding-left:.7em;border-left:.35em solid #9aa5b1}
ul.headline li.tone-good{border-color:#2e9e4f}ul.headline li.tone-bad{border-color:#c62828}
ul.headline li.tone-muted{border-color:#c8ced6;color:#555}
ol.notes{font-size:.9em;color:#333}ol.notes li:target{background:#fff3b0}
.badge{display:inline-block;font-size:.75em;font-weight:bold;color:#8a4b00;background:#ffe2b0;
border:1px solid #d08a2a;border-radius:.3em;padding:0 .4em;margin-left:.4em;vertical-align:middle}
)";

constexpr const char* kBadge = "<span class=\"badge\">synthetic</span>";

std::string Badge(bool synthetic) { return synthetic ? kBadge : ""; }

const char* ToneClass(Tone tone) {
  switch (tone) {
    case Tone::kGood: return "tone-good";
    case Tone::kBad: return "tone-bad";
    case Tone::kMuted: return "tone-muted";
    case Tone::kNeutral: break;
  }
  return "";
}

// Superscript links to the footnotes, "" for none.
std::string NoteMarks(const std::vector<int>& notes) {
  if (notes.empty()) return "";
  std::string out = "<sup class=\"note\">";
  for (size_t k = 0; k < notes.size(); ++k) {
    const std::string n = std::to_string(notes[k]);
    out += (k > 0 ? "," : "") + std::string("<a href=\"#note-") + n + "\">" + n + "</a>";
  }
  return out + "</sup>";
}

std::string FigureHtml(const std::string& svg, const std::string& caption, bool synthetic,
                       int number) {
  const std::string n = std::to_string(number);
  return "<figure id=\"figure-" + n + "\">\n" + svg + "\n<figcaption>Figure " + n + ". " +
         HtmlEscape(caption) + Badge(synthetic) + "</figcaption>\n</figure>\n";
}

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

void HtmlTableBody(const HtmlTable& table, std::string* out) {
  *out += "<div class=\"table-wrap\">\n<table>\n";
  if (!table.caption.empty()) *out += "<caption>" + HtmlEscape(table.caption) + "</caption>\n";
  *out += "<thead><tr>";
  for (const auto& h : table.header) *out += "<th>" + HtmlEscape(h) + "</th>";
  *out += "</tr></thead>\n<tbody>\n";
  for (size_t r = 0; r < table.rows.size(); ++r) {
    bool synthetic = !table.synthetic_rows.empty() && table.synthetic_rows[r];
    *out += synthetic ? "<tr class=\"synthetic\">" : "<tr>";
    const Tone tone = table.row_tones.empty() ? Tone::kNeutral : table.row_tones[r];
    for (size_t c = 0; c < table.rows[r].size(); ++c) {
      const int column = static_cast<int>(c);
      const std::string tone_class = column == table.tone_column ? ToneClass(tone) : "";
      *out += tone_class.empty() ? "<td>" : "<td class=\"" + tone_class + "\">";
      *out += HtmlEscape(table.rows[r][c]) + (c == 0 ? Badge(synthetic) : "");
      if (column == table.note_column && !table.row_notes.empty())
        *out += NoteMarks(table.row_notes[r]);
      *out += "</td>";
    }
    *out += "</tr>\n";
  }
  *out += "</tbody>\n</table>\n</div>\n";
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
  auto refuse = [&](const std::string& why) {
    if (error) *error = "table '" + table.caption + "': " + why;
    return false;
  };
  auto per_row = [&](size_t n, const char* what) {
    return n == 0 || n == table.rows.size()
               ? std::string()
               : std::string(what) + " has " + std::to_string(n) + " entries for " +
                     std::to_string(table.rows.size()) + " rows";
  };
  for (const std::string& why : {per_row(table.synthetic_rows.size(), "synthetic_rows"),
                                 per_row(table.row_tones.size(), "row_tones"),
                                 per_row(table.row_notes.size(), "row_notes")})
    if (!why.empty()) return refuse(why);
  const int columns = static_cast<int>(table.header.size());
  if (table.tone_column < 0 || table.tone_column >= std::max(columns, 1) ||
      table.note_column < 0 || table.note_column >= std::max(columns, 1))
    return refuse("tone_column or note_column outside the " + std::to_string(columns) +
                  " columns");
  for (const auto& notes : table.row_notes)
    for (int n : notes)
      if (n < 1) return refuse("footnote number " + std::to_string(n) + " (they start at 1)");
  for (size_t r = 0; r < table.rows.size(); ++r) {
    if (table.rows[r].size() != table.header.size())
      return refuse("row " + std::to_string(r + 1) + " has " +
                    std::to_string(table.rows[r].size()) + " cells, the header " +
                    std::to_string(table.header.size()));
  }
  blocks_.push_back({.kind = Kind::kTable, .table = table});
  ++table_count_;
  return true;
}

void HtmlReport::Headline(const std::vector<HeadlineItem>& items) {
  blocks_.push_back({.kind = Kind::kHeadline, .headline = items});
}

void HtmlReport::Footnotes(const std::vector<std::string>& notes) {
  blocks_.push_back({.kind = Kind::kFootnotes, .items = notes});
}

bool HtmlReport::FigureRow(const std::vector<HtmlFigure>& figures, std::string* error) {
  std::vector<HtmlFigure> checked;
  for (const HtmlFigure& f : figures) {
    std::string svg = SvgElement(f.svg_document);
    if (svg.empty()) {
      if (error) *error = "figure '" + f.caption + "': not a single <svg>...</svg> element";
      return false;
    }
    checked.push_back({.svg_document = std::move(svg), .caption = f.caption,
                       .synthetic = f.synthetic});
  }
  if (checked.empty()) return true;
  figure_count_ += static_cast<int>(checked.size());
  blocks_.push_back({.kind = Kind::kFigureRow, .figures = std::move(checked)});
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
      case Kind::kFigure: out += FigureHtml(b.svg, b.text, b.synthetic, ++figure); break;
      case Kind::kFigureRow:
        out += "<div class=\"figure-row\">\n";
        for (const HtmlFigure& f : b.figures)
          out += FigureHtml(f.svg_document, f.caption, f.synthetic, ++figure);
        out += "</div>\n";
        break;
      case Kind::kHeadline:
        out += "<ul class=\"headline\">\n";
        for (const HeadlineItem& item : b.headline) {
          const std::string tone = ToneClass(item.tone);
          out += (tone.empty() ? "<li>" : "<li class=\"" + tone + "\">") + "<strong>" +
                 HtmlEscape(item.label) + "</strong> " + HtmlEscape(item.text) +
                 NoteMarks(item.notes) + "</li>\n";
        }
        out += "</ul>\n";
        break;
      case Kind::kFootnotes:
        out += "<ol class=\"notes\">\n";
        for (size_t k = 0; k < b.items.size(); ++k)
          out += "<li id=\"note-" + std::to_string(k + 1) + "\">" + HtmlEscape(b.items[k]) +
                 "</li>\n";
        out += "</ol>\n";
        break;
    }
  }
  if (section_open) out += "</section>\n";
  out += "</body>\n</html>\n";
  return out;
}

bool HtmlReport::WriteFile(const std::string& path, std::string* error) const {
  return core::io::WriteFileAtomically(path, [this](std::ostream& out) { out << Document(); },
                                       error);
}

}  // namespace demcal::workflow
