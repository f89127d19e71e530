#include "workflow/reproduce/summary_table.h"

#include <catch2/catch.hpp>
#include <cmath>

using namespace demcal::workflow;

namespace {
ReferenceValue Ref(const std::string& key, double value, double u = 0,
                   const std::string& comparison = "equal") {
  ReferenceValue r;
  r.key = key;
  r.quantity = key;
  r.value = value;
  r.uncertainty = u;
  r.comparison = comparison;
  r.unit = "J/m2";
  r.source = "stand-in";
  return r;
}
}  // namespace

TEST_CASE("summary rows: every reference gets a row and a verdict from stand-in numbers", "[unit]") {
  const std::vector<ReferenceValue> refs = {
      Ref("gamma_w0.5_J_m2", 0.046, 0.0),          // within its sem
      Ref("gamma_sim_J_m2", 0.046),                // deterministic, differs
      Ref("angle_EP_deg", 31.0, 1.0),              // differs by 3 σ
      Ref("ep_cov_reduction_pct", 40, 0, "at_least"),
      Ref("s_n_EP_3d_coated", 1.0, 0, "at_most"),
      Ref("cov_EP_3d_uncoated", NAN),              // figure only
      Ref("s_n_EP_3d_excessive", 2.58)};           // not run
  DemcalValues v;
  v["gamma_w0.5_J_m2"] = {.mean = 0.050, .sem = 0.006, .synthetic = false};
  v["gamma_sim_J_m2"] = {.mean = 0.0409, .note = "Γ ∝ E^(2/5)"};
  v["angle_EP_deg"] = {.mean = 34.0, .sem = 0.0};
  v["ep_cov_reduction_pct"] = {.mean = 25, .sem = 5, .synthetic = true};
  v["s_n_EP_3d_coated"] = {.mean = 0.9, .sem = 0.1};
  v["cov_EP_3d_uncoated"] = {.mean = 1.1, .sem = 0.1};
  v["s_n_EP_3d_excessive"] = {.note = "segregation disabled"};
  const std::vector<SummaryRow> rows = BuildSummaryRows(refs, v);
  REQUIRE(rows.size() == refs.size());
  CHECK(rows[0].verdict == "within noise");
  CHECK(rows[1].verdict.find("differs by -0.0051") == 0);
  CHECK(rows[1].verdict.find("no noise to compare with") != std::string::npos);
  CHECK(rows[1].note == "Γ ∝ E^(2/5)");
  CHECK(rows[2].verdict == "differs by 3 J/m2 (3 σ)");
  CHECK(rows[3].verdict.find("does not meet (≥ 40") == 0);
  CHECK(rows[3].synthetic);
  CHECK(rows[4].verdict.find("meets (≤ 1") == 0);
  CHECK(rows[5].verdict.find("demcal only") == 0);
  CHECK(rows[6].verdict == "not run: segregation disabled");
}

TEST_CASE("summary.json has one row per reference with nulls for missing numbers", "[unit]") {
  std::vector<ReferenceValue> refs = {Ref("coh_coated_EP", 1.6e-3), Ref("ep_outflow_fraction", NAN)};
  DemcalValues v;
  v["coh_coated_EP"] = {.mean = 1.64e-3};
  const auto j = SummaryJson("alizadeh2018", "quick", BuildSummaryRows(refs, v));
  CHECK(j["format"] == "demcal-reproduce-summary/1");
  REQUIRE(j["rows"].size() == 2);
  CHECK(j["rows"][0]["demcal_mean"].get<double>() == Approx(1.64e-3));
  CHECK(j["rows"][0]["demcal_sem"].is_null());
  CHECK(j["rows"][1]["paper_value"].is_null());
  CHECK(j["rows"][1]["demcal_mean"].is_null());
  for (const auto& row : j["rows"])
    for (const char* key : {"quantity", "paper_value", "demcal_mean", "demcal_sem", "verdict", "source"})
      CHECK(row.contains(key));
}

TEST_CASE("summary rows: a number that does not measure the paper's quantity is not compared", "[unit]") {
  DemcalValues v;
  v["discharge_time_uncoated_s"] = {.mean = 1.6, .note = "feed-limited funnel", .comparable = false};
  const std::vector<SummaryRow> rows = BuildSummaryRows({Ref("discharge_time_uncoated_s", 2.22)}, v);
  REQUIRE(rows.size() == 1);
  CHECK(rows[0].verdict == "not comparable: feed-limited funnel");
  CHECK(rows[0].demcal_mean == Approx(1.6));  // the number is still shown
}

TEST_CASE("summary rows: the verdict kind comes with the text; the short verdict drops the note",
          "[unit]") {
  const std::string long_note(400, 'x');
  DemcalValues v;
  v["a"] = {.mean = 1.0, .sem = 0.1};                 // within noise
  v["b"] = {.mean = 5.0};                             // differs
  v["c"] = {.note = long_note};                       // not run, with why
  v["d"] = {};                                        // not run, no why
  v["e"] = {.mean = 2, .note = long_note, .comparable = false};
  v["f"] = {.mean = 50};                              // meets (≥ 40)
  v["g"] = {.mean = 0.5};                             // figure only
  const std::vector<SummaryRow> rows = BuildSummaryRows(
      {Ref("a", 1.05), Ref("b", 1.0, 0.5), Ref("c", 3), Ref("d", 3), Ref("e", 2.2),
       Ref("f", 40, 0, "at_least"), Ref("g", NAN)},
      v);
  REQUIRE(rows.size() == 7);
  CHECK(rows[0].kind == VerdictKind::kWithinNoise);
  CHECK(rows[1].kind == VerdictKind::kDiffers);
  CHECK(rows[2].kind == VerdictKind::kNotRun);
  CHECK(rows[3].kind == VerdictKind::kNotRun);
  CHECK(rows[4].kind == VerdictKind::kNotComparable);
  CHECK(rows[5].kind == VerdictKind::kMeets);
  CHECK(rows[6].kind == VerdictKind::kDemcalOnly);
  CHECK(ShortVerdict(rows[0]) == "within noise");
  CHECK(ShortVerdict(rows[1]) == rows[1].verdict);  // "differs by 4 J/m2 (8 σ)": already short
  CHECK(ShortVerdict(rows[2]) == "not run");
  CHECK(rows[2].verdict.find(long_note) != std::string::npos);  // summary.json keeps it whole
  CHECK(ShortVerdict(rows[3]) == "not run: no value at this fidelity");  // no note to point at
  CHECK(ShortVerdict(rows[4]) == "not comparable");
  CHECK(ShortVerdict(rows[6]) == "demcal only");
  for (const SummaryRow& row : rows) CHECK(ShortVerdict(row).size() < 60);
}
