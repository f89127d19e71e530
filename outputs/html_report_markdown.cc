// The Markdown twin of HtmlReport (html_report.h): the same blocks in the same order, figures as
// image links to SVG files written beside it, footnote marks as "[k]" and notes as a numbered list.
#include <cstdio>
#include <filesystem>

#include "core/io/atomic_file.h"
#include "outputs/html_report.h"

namespace demcal::workflow {
namespace {

std::string MarkdownCell(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '|') out += "\\|";
    else if (c == '\n') out += ' ';
    else out += c;
  }
  return out;
}

// " [1]", " [1, 3]", or "" for none.
std::string NoteMarks(const std::vector<int>& notes) {
  if (notes.empty()) return "";
  std::string out = " [";
  for (size_t k = 0; k < notes.size(); ++k) out += (k > 0 ? ", " : "") + std::to_string(notes[k]);
  return out + "]";
}

void MarkdownTableBody(const HtmlTable& table, std::string* out) {
  if (!table.caption.empty()) *out += "**" + MarkdownCell(table.caption) + "**\n\n";
  *out += "|";
  for (const auto& h : table.header) out->append(" ").append(MarkdownCell(h)).append(" |");
  *out += "\n|";
  for (size_t c = 0; c < table.header.size(); ++c) *out += " --- |";
  *out += "\n";
  for (size_t r = 0; r < table.rows.size(); ++r) {
    bool synthetic = !table.synthetic_rows.empty() && table.synthetic_rows[r];
    *out += "|";
    for (size_t c = 0; c < table.rows[r].size(); ++c) {
      const bool marked = static_cast<int>(c) == table.note_column && !table.row_notes.empty();
      *out += " " + MarkdownCell(table.rows[r][c]) +
              (c == 0 && synthetic ? " **[synthetic]**" : "") +
              (marked ? NoteMarks(table.row_notes[r]) : "") + " |";
    }
    *out += "\n";
  }
  *out += "\n";
}

std::string FigureMarkdown(const std::string& figure_dir, const std::string& caption,
                           bool synthetic, int k) {
  const std::string n = std::to_string(k + 1);
  return "![Figure " + n + "](" + figure_dir + "/" + HtmlReport::FigureFileName(k) +
         ")\n\n*Figure " + n + ". " + caption + "*" + (synthetic ? " **[synthetic]**" : "") +
         "\n\n";
}

}  // namespace

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
      case Kind::kParagraph:
        out += (b.synthetic ? "**[synthetic]** " : "") + b.text + "\n\n";
        break;
      case Kind::kList:
        for (const auto& item : b.items) out += "- " + item + "\n";
        out += "\n";
        break;
      case Kind::kCode: out += "```\n" + b.text + "\n```\n\n"; break;
      case Kind::kTable: MarkdownTableBody(b.table, &out); break;
      case Kind::kFigure: out += FigureMarkdown(figure_dir, b.text, b.synthetic, figure++); break;
      case Kind::kFigureRow:
        for (const HtmlFigure& f : b.figures)
          out += FigureMarkdown(figure_dir, f.caption, f.synthetic, figure++);
        break;
      case Kind::kHeadline:
        for (const HeadlineItem& item : b.headline)
          out += "- **" + item.label + "** " + item.text + NoteMarks(item.notes) + "\n";
        out += "\n";
        break;
      case Kind::kFootnotes:
        for (size_t k = 0; k < b.items.size(); ++k)
          out += std::to_string(k + 1) + ". " + b.items[k] + "\n";
        out += "\n";
        break;
    }
  }
  return out;
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
  std::vector<const std::string*> svgs;
  for (const Block& b : blocks_) {
    if (b.kind == Kind::kFigure) svgs.push_back(&b.svg);
    if (b.kind == Kind::kFigureRow)
      for (const HtmlFigure& f : b.figures) svgs.push_back(&f.svg_document);
  }
  for (size_t k = 0; k < svgs.size(); ++k) {
    const std::string& svg = *svgs[k];
    const std::string path = (dir / FigureFileName(static_cast<int>(k))).string();
    if (!core::io::WriteFileAtomically(path, [&svg](std::ostream& out) { out << svg << "\n"; },
                                       error)) {
      return false;
    }
  }
  std::string md = Markdown(figure_dir);
  return core::io::WriteFileAtomically(md_path, [&md](std::ostream& out) { out << md; }, error);
}

}  // namespace demcal::workflow
