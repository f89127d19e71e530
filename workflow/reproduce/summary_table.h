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

// The verdict as a kind, for whatever groups or colours rows (the report's headline): decided with
// the verdict's text, never read back from it.
enum class VerdictKind {
  kWithinNoise,    // "within noise"
  kMeets,          // "meets (≥ v)"
  kDiffers,        // "differs by X (k σ)"
  kDoesNotMeet,    // "does not meet (≥ v)"
  kDemcalOnly,     // the paper gives a figure, no number
  kNotComparable,  // demcal's number measures something else (note says why)
  kNotRun,         // no demcal value
};

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
  VerdictKind kind = VerdictKind::kNotRun;
  bool synthetic = false;
};

std::vector<SummaryRow> BuildSummaryRows(const std::vector<ReferenceValue>& reference,
                                         const DemcalValues& values);
std::string Verdict(const ReferenceValue& reference, const DemcalValue& value);
VerdictKind ClassifyVerdict(const ReferenceValue& reference, const DemcalValue& value);
// The verdict without the note it may carry ("not run", "not comparable" when the row has a note;
// "demcal only"; the rest as Verdict() has it): for a table whose notes are printed once, below
// it, and whose text says what "demcal only" means.
std::string ShortVerdict(const SummaryRow& row);

// summary.json: {"format": "demcal-reproduce-summary/1", "workflow", "fidelity", "rows": [...]}
// (NaN written as null).
nlohmann::ordered_json SummaryJson(const std::string& workflow_name, const std::string& fidelity,
                                   const std::vector<SummaryRow>& rows);

}  // namespace demcal::workflow
