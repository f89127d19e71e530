#pragma once
// The verdict-first parts of the reproduce report, computed from the summary rows alone (no stage
// results, no files): the headline a reader sees first (what matched the paper, what did not,
// what was not compared, what was not run and why) and the table's notes as numbered footnotes,
// each distinct note once however many rows share it.
//
//   const RowNotes notes = NumberRowNotes(rows);
//   report.Headline(VerdictHeadline(rows, notes));
//   ... the table with ShortVerdict(row) and notes.row_notes ...; report.Footnotes(notes.notes);
#include <string>
#include <vector>

#include "outputs/html_report.h"
#include "workflow/reproduce/summary_table.h"

namespace demcal::workflow {

struct RowNotes {
  std::vector<std::string> notes;           // each distinct note once, in order of first use
  std::vector<std::vector<int>> row_notes;  // per row, its footnote numbers (1-based; 0 or 1 each)
};

RowNotes NumberRowNotes(const std::vector<SummaryRow>& rows);

// good: matched; bad: did not match; muted: no comparison (not run, not comparable, demcal only).
Tone VerdictTone(VerdictKind kind);

// The headline lines: matched, did not match, not compared, not run (one line per reason), and
// how many rows rest on synthetic data; a line with nothing to say is left out.
std::vector<HeadlineItem> VerdictHeadline(const std::vector<SummaryRow>& rows,
                                          const RowNotes& notes);

}  // namespace demcal::workflow
