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
