#include "workflow/reproduce/report_headline.h"

#include <catch2/catch.hpp>
#include <cmath>

using namespace demcal::workflow;

namespace {

ReferenceValue Ref(const std::string& key, const std::string& quantity, double value,
                   double u = 0) {
  ReferenceValue r;
  r.key = key;
  r.quantity = quantity;
  r.value = value;
  r.uncertainty = u;
  r.unit = "-";
  r.source = "stand-in";
  return r;
}

// A stand-in for the workflow's long shape note, shared by the three clump-count rows.
const std::string kShapeNote =
    "shape fixed by the workflow file: every species is modelled as spheres, the paper's clumps "
    "have no published aspect ratios, so the rolling friction stands in for the shape";

std::vector<SummaryRow> StandInRows() {
  DemcalValues v;
  v["angle_BP_deg"] = {.mean = 40.3, .sem = 0.4, .note = "calibrated to it"};
  v["angle_EP_deg"] = {.mean = 35.0, .sem = 0.2, .note = "not matched: budget"};
  v["clump_count_BP"] = {.note = kShapeNote};
  v["clump_count_TAED"] = {.note = kShapeNote};
  v["clump_count_EP"] = {.note = kShapeNote};
  v["gamma_w2.5_J_m2"] = {.mean = 0.25, .sem = 0.02, .synthetic = true};
  v["cov_EP_3d_uncoated"] = {.mean = 1.1, .sem = 0.1};
  v["discharge_time_uncoated_s"] = {.mean = 1.6, .note = "feed-limited", .comparable = false};
  v["fidelity_angle_shift_deg"] = {};
  return BuildSummaryRows(
      {Ref("angle_BP_deg", "BP repose angle", 40, 1),
       Ref("angle_EP_deg", "EP repose angle, uncoated", 31, 1),
       Ref("clump_count_BP", "BP clump sphere count", 5),
       Ref("clump_count_TAED", "TAED clump sphere count", 5),
       Ref("clump_count_EP", "EP clump sphere count (1-3)", 3),
       Ref("gamma_w2.5_J_m2", "Gamma EP-EP at 2.5 wt% (circular: its angle is synthetic)", 0.25),
       Ref("cov_EP_3d_uncoated", "EP CoV whole heap, uncoated", NAN),
       Ref("discharge_time_uncoated_s", "funnel discharge time, uncoated", 2.22),
       Ref("fidelity_angle_shift_deg", "EP angle shift at a finer fidelity", 0)},
      v);
}

const HeadlineItem* Line(const std::vector<HeadlineItem>& lines, const std::string& label,
                         const std::string& containing = "") {
  for (const HeadlineItem& line : lines)
    if (line.label == label && line.text.find(containing) != std::string::npos) return &line;
  return nullptr;
}

}  // namespace

TEST_CASE("report notes: a note shared by several rows is numbered once", "[unit]") {
  const std::vector<SummaryRow> rows = StandInRows();
  const RowNotes notes = NumberRowNotes(rows);
  REQUIRE(notes.row_notes.size() == rows.size());
  int shape = 0;
  for (const std::string& n : notes.notes) shape += n == kShapeNote;
  CHECK(shape == 1);
  CHECK(notes.notes.size() == 4);  // calibrated, not matched, shape, feed-limited
  CHECK(notes.row_notes[2] == notes.row_notes[3]);
  CHECK(notes.row_notes[3] == notes.row_notes[4]);
  CHECK(notes.notes[notes.row_notes[2][0] - 1] == kShapeNote);
  CHECK(notes.row_notes[5].empty());  // no note, no mark
  CHECK(notes.row_notes[0] == std::vector<int>{1});  // numbered in order of first use
}

TEST_CASE("report headline: matched, did not match, not compared, not run, synthetic", "[unit]") {
  const std::vector<SummaryRow> rows = StandInRows();
  const RowNotes notes = NumberRowNotes(rows);
  const std::vector<HeadlineItem> lines = VerdictHeadline(rows, notes);
  // Compared: BP angle (within noise), EP angle (differs), Γ at 2.5 (within noise, synthetic).
  const HeadlineItem* matched = Line(lines, "Matched the paper:");
  REQUIRE(matched != nullptr);
  CHECK(matched->text == "2 of 3 compared: BP repose angle; Gamma EP-EP at 2.5 wt% (synthetic)");
  CHECK(matched->tone == Tone::kGood);
  const HeadlineItem* missed = Line(lines, "Did not match:");
  REQUIRE(missed != nullptr);
  CHECK(missed->text == "1 of 3 compared: EP repose angle, uncoated");
  CHECK(missed->tone == Tone::kBad);
  // The three clump counts share one line and one footnote; the shift without a note says so.
  const HeadlineItem* clumps = Line(lines, "Not run:", "clump");
  REQUIRE(clumps != nullptr);
  CHECK(clumps->text ==
        "BP clump sphere count; TAED clump sphere count; EP clump sphere count");
  CHECK(clumps->notes == notes.row_notes[2]);
  CHECK(clumps->text.find(kShapeNote) == std::string::npos);  // the long note is the footnote's
  const HeadlineItem* shift = Line(lines, "Not run:", "shift");
  REQUIRE(shift != nullptr);
  CHECK(shift->text == "EP angle shift at a finer fidelity (no value at this fidelity)");
  CHECK(shift->notes.empty());
  const HeadlineItem* feed = Line(lines, "Not comparable:");
  REQUIRE(feed != nullptr);
  CHECK(feed->notes == notes.row_notes[7]);
  CHECK(Line(lines, "Figure only in the paper:", "1 quantity ") != nullptr);
  CHECK(Line(lines, "Synthetic inputs:", "1 row rests") != nullptr);
  // The verdict reads in that order: matched first, then the misses, then what was not compared.
  CHECK(lines[0].label == "Matched the paper:");
  CHECK(lines[1].label == "Did not match:");
}

TEST_CASE("report headline: nothing compared and nothing missed say so without empty lines",
          "[unit]") {
  DemcalValues v;
  v["a"] = {.mean = 1.0};
  const std::vector<SummaryRow> matched = BuildSummaryRows({Ref("a", "alpha", 1.0)}, v);
  const std::vector<HeadlineItem> lines = VerdictHeadline(matched, NumberRowNotes(matched));
  REQUIRE(lines.size() == 1);
  CHECK(lines[0].text == "1 of 1 compared: alpha");
  const std::vector<SummaryRow> none = BuildSummaryRows({Ref("b", "beta", 1.0)}, {});
  const std::vector<HeadlineItem> empty = VerdictHeadline(none, NumberRowNotes(none));
  REQUIRE(empty.size() == 2);
  CHECK(empty[0].label == "Compared with the paper:");
  CHECK(empty[1].label == "Not run:");
}

TEST_CASE("report headline: a long list of rows is cut to a few names and a count", "[unit]") {
  std::vector<ReferenceValue> refs;
  for (int k = 0; k < 12; ++k) {
    const std::string name = std::string("q").append(std::to_string(k));
    refs.push_back(Ref(name, name, 1));
  }
  const std::vector<SummaryRow> rows = BuildSummaryRows(refs, {});
  const std::vector<HeadlineItem> lines = VerdictHeadline(rows, NumberRowNotes(rows));
  const HeadlineItem* not_run = Line(lines, "Not run:");
  REQUIRE(not_run != nullptr);
  CHECK(not_run->text == "q0; q1; q2; q3; q4; q5; q6; and 5 more (no value at this fidelity)");
}
