#pragma once
// The paper-vs-demcal table of `demcal reproduce` (summary.json, and the report's first table):
// one row per reference number of the workflow file (reference[]), with demcal's mean and
// standard error where a stage computed it, and a verdict:
//   "within noise"           |demcal − paper| ≤ √(sem² + u²) — the calibration's own criterion
//                            (docs/calibration.md), u the reference's uncertainty (0 if none);
//   "differs by X (k σ)"     otherwise, with the likely cause in `note` where one is known;
//   "meets (≥ v)" / "does not meet (≥ v)"  for an at_least / at_most reference (the paper's
//                            "CoV at least 40 % lower after coating");
//   "demcal only"            the paper shows it in a figure, without a number;
//   "not run: <why>"         no demcal value (a disabled stage, or not run at this fidelity).
// A synthetic input (an angle made by scripts/make_synthetic_coating_angles.py) marks the row.
//
//   DemcalValues v;  v["coh_coated_EP"] = {.mean = 1.64e-3, .sem = 0};
//   std::vector<SummaryRow> rows = BuildSummaryRows(workflow.reference, v);
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "workflow/reproduce/workflow_file.h"

namespace demcal::workflow {

struct DemcalValue {
  double mean = std::numeric_limits<double>::quiet_NaN();
  double sem = std::numeric_limits<double>::quiet_NaN();  // NaN: no spread (deterministic)
  std::string note;        // the likely cause of a difference, or why it was not run
  bool synthetic = false;  // computed from synthetic data
  bool comparable = true;  // false: the number does not measure the paper's quantity (note says why)
};
using DemcalValues = std::map<std::string, DemcalValue>;

struct SummaryRow {
  std::string key, quantity, unit, source, comparison;
  double paper_value = std::numeric_limits<double>::quiet_NaN();
  double paper_uncertainty = 0;
  double demcal_mean = std::numeric_limits<double>::quiet_NaN();
  double demcal_sem = std::numeric_limits<double>::quiet_NaN();
  std::string verdict, note;
  bool synthetic = false;
};

std::vector<SummaryRow> BuildSummaryRows(const std::vector<ReferenceValue>& reference,
                                         const DemcalValues& values);
std::string Verdict(const ReferenceValue& reference, const DemcalValue& value);

// summary.json: {"format": "demcal-reproduce-summary/1", "workflow", "fidelity", "rows": [...]}
// (NaN written as null).
nlohmann::ordered_json SummaryJson(const std::string& workflow_name, const std::string& fidelity,
                                   const std::vector<SummaryRow>& rows);

}  // namespace demcal::workflow
