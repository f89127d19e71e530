#include "workflow/reproduce/report_headline.h"

#include <map>

namespace demcal::workflow {
namespace {

bool Compared(VerdictKind kind) {
  return kind == VerdictKind::kWithinNoise || kind == VerdictKind::kMeets ||
         kind == VerdictKind::kDiffers || kind == VerdictKind::kDoesNotMeet;
}

bool Matched(VerdictKind kind) {
  return kind == VerdictKind::kWithinNoise || kind == VerdictKind::kMeets;
}

// The quantity without its parenthetical detail ("EP clump sphere count (1-3)" -> "EP clump
// sphere count"): the headline names rows, the table gives the detail.
std::string ShortName(const SummaryRow& row) {
  const size_t paren = row.quantity.find(" (");
  std::string name = paren == std::string::npos ? row.quantity : row.quantity.substr(0, paren);
  return row.synthetic ? name + " (synthetic)" : name;
}

// The rows' names; past kMaxNames, a count of the rest: a headline line stays a line, the table
// lists them all.
constexpr size_t kMaxNames = 8;

std::string Names(const std::vector<const SummaryRow*>& rows) {
  std::string out;
  const size_t shown = rows.size() > kMaxNames ? kMaxNames - 1 : rows.size();
  for (size_t k = 0; k < shown; ++k) out += (k > 0 ? "; " : "") + ShortName(*rows[k]);
  if (shown < rows.size()) out += "; and " + std::to_string(rows.size() - shown) + " more";
  return out;
}

std::string Count(size_t n, const char* one, const char* many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

// One line per distinct note among the rows of `kind` (rows without a note share one line,
// `no_note` in words), each naming its rows and marking its footnote.
void GroupedLines(const std::vector<SummaryRow>& rows, const RowNotes& notes, VerdictKind kind,
                  const std::string& label, const std::string& no_note,
                  std::vector<HeadlineItem>* out) {
  std::map<int, std::vector<const SummaryRow*>> groups;  // footnote number (0: none) -> rows
  for (size_t r = 0; r < rows.size(); ++r) {
    if (rows[r].kind != kind) continue;
    groups[notes.row_notes[r].empty() ? 0 : notes.row_notes[r][0]].push_back(&rows[r]);
  }
  for (const auto& [note, members] : groups) {
    HeadlineItem item{.label = label, .text = Names(members), .tone = Tone::kMuted};
    if (note == 0) item.text += " (" + no_note + ")";
    else item.notes = {note};
    out->push_back(item);
  }
}

}  // namespace

RowNotes NumberRowNotes(const std::vector<SummaryRow>& rows) {
  RowNotes out;
  std::map<std::string, int> number;
  for (const SummaryRow& row : rows) {
    out.row_notes.emplace_back();
    if (row.note.empty()) continue;
    auto [it, added] = number.emplace(row.note, static_cast<int>(out.notes.size()) + 1);
    if (added) out.notes.push_back(row.note);
    out.row_notes.back().push_back(it->second);
  }
  return out;
}

Tone VerdictTone(VerdictKind kind) {
  if (Matched(kind)) return Tone::kGood;
  if (Compared(kind)) return Tone::kBad;
  return Tone::kMuted;
}

std::vector<HeadlineItem> VerdictHeadline(const std::vector<SummaryRow>& rows,
                                          const RowNotes& notes) {
  std::vector<const SummaryRow*> matched, missed;
  size_t figure_only = 0, synthetic = 0;
  for (const SummaryRow& row : rows) {
    if (Matched(row.kind)) matched.push_back(&row);
    else if (Compared(row.kind)) missed.push_back(&row);
    figure_only += row.kind == VerdictKind::kDemcalOnly;
    synthetic += row.synthetic;
  }
  const size_t compared = matched.size() + missed.size();
  std::vector<HeadlineItem> out;
  if (compared == 0) {
    out.push_back({.label = "Compared with the paper:",
                   .text = "nothing: no row has both a paper number and a demcal value"});
  } else {
    const std::string of = " of " + std::to_string(compared) + " compared";
    out.push_back({.label = "Matched the paper:",
                   .text = matched.empty() ? "none" + of
                                           : std::to_string(matched.size()) + of + ": " +
                                                 Names(matched),
                   .tone = matched.empty() ? Tone::kNeutral : Tone::kGood});
    if (!missed.empty())
      out.push_back({.label = "Did not match:",
                     .text = std::to_string(missed.size()) + of + ": " + Names(missed),
                     .tone = Tone::kBad});
  }
  GroupedLines(rows, notes, VerdictKind::kNotComparable, "Not comparable:", "see the table",
               &out);
  GroupedLines(rows, notes, VerdictKind::kNotRun, "Not run:", "no value at this fidelity", &out);
  if (figure_only > 0)
    out.push_back({.label = "Figure only in the paper:",
                   .text = Count(figure_only, "quantity", "quantities") +
                           " without a number to compare with; demcal's values are in the table",
                   .tone = Tone::kMuted});
  if (synthetic > 0)
    out.push_back({.label = "Synthetic inputs:",
                   .text = Count(synthetic, "row rests", "rows rest") +
                           " on synthetic data, not on measurements (marked synthetic in the "
                           "table)"});
  return out;
}

}  // namespace demcal::workflow
