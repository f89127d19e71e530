#pragma once
// HtmlReport: a self-contained HTML report (one file, no scripts, no network: figures are inline
// SVG, the style sheet is inline), built as a document of sections. Shared by the workflows that
// end in a report a user opens in a browser (`demcal reproduce`, `demcal diagnose`).
//
// Every text argument is plain text and is HTML-escaped here; only Figure() takes markup (an SVG
// document, as written by objectives/report/svg_canvas.h or svg_plot.h), which is checked to be one
// <svg> element and stripped of any XML prologue. Anything derived from synthetic data carries a
// visible "synthetic" badge: pass synthetic = true to the section, paragraph, table row or figure.
// WriteFile is atomic (temporary file, fsync, rename: core/io/atomic_file.h), so a kill leaves
// the previous report or the new one, never half of one.
//
// A report that leads with its verdict uses Headline() (a few labelled lines in a box), FigureRow()
// (figures side by side where the screen is wide) and tables whose long notes are numbered
// footnotes (HtmlTable::row_notes, then Footnotes() below the table). The page fills the width of
// the window; wide tables scroll sideways on a narrow one.
//
// Thread-safety: a plain value; build it on one thread.
//
//   HtmlReport report("demcal reproduce alizadeh2018");
//   report.Section("Γ per coating level");
//   report.Paragraph("Γ of EP–EP calibrated to each level's repose angle.");
//   report.Table({.caption = "Γ", .header = {"w [wt%]", "Γ [J/m²]"}, .rows = {{"0.5", "0.041"}}});
//   report.Figure(objectives::RenderSvg(plot), "Fig. 6 style", /*synthetic=*/true);
//   if (!report.WriteFile(dir + "/report.html", &error)) ...
#include <string>
#include <vector>

namespace demcal::workflow {

// How a verdict reads at a glance: the colour of a headline line or of a table's tone cell.
enum class Tone { kNeutral, kGood, kBad, kMuted };

struct HtmlTable {
  std::string caption;                          // may be empty
  std::vector<std::string> header;              // column titles, units in brackets
  std::vector<std::vector<std::string>> rows;   // each as wide as header
  std::vector<bool> synthetic_rows;             // empty, or one flag per row (badge on the row)
  std::vector<Tone> row_tones;                  // empty, or one per row: colours cell tone_column
  int tone_column = 0;
  std::vector<std::vector<int>> row_notes;      // empty, or per row the footnote numbers (1-based)
  int note_column = 0;                          // marked after the text of this column
};

// One line of a headline: a bold label, then plain text, then footnote marks.
struct HeadlineItem {
  std::string label;       // "Matched the paper"
  std::string text;        // "6 of 14 compared: ..."
  std::vector<int> notes;  // footnote numbers (1-based), linked to Footnotes()
  Tone tone = Tone::kNeutral;
};

struct HtmlFigure {
  std::string svg_document;  // as for HtmlReport::Figure
  std::string caption;
  bool synthetic = false;
};

class HtmlReport {
 public:
  // `title` becomes the <title> and the page's <h1>.
  explicit HtmlReport(std::string title);

  // Opens a new section (<h2>); the previous one, if any, is closed.
  void Section(const std::string& heading, bool synthetic = false);
  // A sub-heading inside the current section (<h3>).
  void Subheading(const std::string& heading);
  void Paragraph(const std::string& text, bool synthetic = false);
  // A bulleted list.
  void List(const std::vector<std::string>& items);
  // Monospaced text kept as is (commands, file listings).
  void Code(const std::string& text);
  // A table; false (and nothing added) if a row is not as wide as the header, a per-row list has
  // the wrong length, or a column index or footnote number is out of range, with the reason in
  // *error.
  bool Table(const HtmlTable& table, std::string* error);
  // The verdict lines a reader sees first (a boxed list; in Markdown "- **label** text [k]").
  void Headline(const std::vector<HeadlineItem>& items);
  // Numbered notes (1, 2, ... in order; note k is the target of the marks [k]).
  void Footnotes(const std::vector<std::string>& notes);
  // An inline SVG figure with a caption; false (nothing added) if `svg_document` is not one
  // <svg ...>...</svg> element (after an optional <?xml ...?> prologue).
  bool Figure(const std::string& svg_document, const std::string& caption, bool synthetic,
              std::string* error);
  // Figures side by side where the window is wide enough, one under the other where not; each is
  // numbered as Figure() numbers it. False (nothing added) if any is malformed.
  bool FigureRow(const std::vector<HtmlFigure>& figures, std::string* error);

  // The whole page.
  std::string Document() const;
  // The same document as Markdown: figure k (0-based) appears as an image link to
  // `figure_dir/FigureFileName(k)`, synthetic parts as "**[synthetic]**".
  std::string Markdown(const std::string& figure_dir) const;
  // Writes `md_path` (Markdown(figure_dir)) and every figure as an SVG file under the directory
  // `figure_dir` relative to md_path's directory (created if needed), each atomically.
  bool WriteMarkdown(const std::string& md_path, const std::string& figure_dir,
                     std::string* error) const;
  // "figure_01.svg", "figure_02.svg", ... for k = 0, 1, ...
  static std::string FigureFileName(int k);
  // Writes Document() to `path` atomically; false with "cannot write '<path>': reason".
  bool WriteFile(const std::string& path, std::string* error) const;

  int figure_count() const { return figure_count_; }
  int table_count() const { return table_count_; }

 private:
  enum class Kind {
    kSection, kSubheading, kParagraph, kList, kCode, kTable, kFigure, kFigureRow, kHeadline,
    kFootnotes
  };
  struct Block {
    Kind kind;
    std::string text;                 // heading, paragraph, code, figure caption
    std::vector<std::string> items;   // list, footnotes
    HtmlTable table;
    std::string svg;                  // figure, without prologue
    bool synthetic = false;
    std::vector<HtmlFigure> figures;  // figure row, each svg without prologue
    std::vector<HeadlineItem> headline;
  };
  std::string title_;
  std::vector<Block> blocks_;
  int figure_count_ = 0;
  int table_count_ = 0;
};

// Escapes &, <, >, " and ' for HTML text and attribute values.
std::string HtmlEscape(const std::string& text);

}  // namespace demcal::workflow
