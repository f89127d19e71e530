#pragma once
// MeasurementTable: the tidy table of measured values that calibration and diagnosis read
// (datasets/README.md). One row per measured value:
//   observable   a registered observable name, unit in the name (calibrate/observable_registry.h)
//   unit         the observable's unit, checked against the registry
//   material     a material, or "mixture" for a blend
//   <conditions> any other column: what distinguishes the row (coating_PEG_wt_pct, diameter_m,
//                test, ...); a number or a word; empty = does not apply
//   value        in the unit; inside the observable's physical range
//   uncertainty  one standard deviation (> 0), or empty when the source gives none
//   repeats      how many repeats the value is the mean of (>= 1), or empty
//   provenance   measured, inferred (read from a source's text, not a measurement), synthetic
//                (made by demcal) or simulated:<engine> (made by another simulator, e.g.
//                simulated:liggghts-3.8; engine: lower-case letters, digits, '.', '-', '_')
//   source       where the number came from (paper, table, figure, page; or the synthetic recipe)
// Checked on load: every field's type and range; two rows for the same observable, material and
// conditions are an error naming both lines. Errors read "FILE:LINE: column: problem".
//
//   MeasurementTable table;
//   if (!LoadMeasurementTable(path, &table, &error)) ...;
//   const MeasurementRow* row = table.Find("angle_deg", "BP", {{"coating_PEG_wt_pct", "0"}}, &error);
//
// Thread-safety: immutable after loading.
#include <string>
#include <vector>

#include "calibrate/condition.h"

namespace demcal::workflow {

struct MeasurementRow {
  int line = 0;  // in the file, 1 = header
  std::string observable, unit, material;
  calibrate::Condition conditions;  // column -> cell (empty cells left out)
  double value = 0;
  double uncertainty = 0;  // 0: not given
  int repeats = 0;         // 0: not given
  std::string provenance;  // measured, inferred, synthetic, simulated:<engine>
  std::string source;
  bool HasUncertainty() const { return uncertainty > 0; }
};

struct MeasurementTable {
  std::string path;
  std::vector<std::string> condition_columns;
  std::vector<MeasurementRow> rows;
  // The one row of this observable and material whose conditions include `conditions` (a number
  // matches a number of the same value: "0.5" = "0.50"). nullptr with *error naming the table
  // and what matched (none, or several: then which condition would tell them apart).
  const MeasurementRow* Find(const std::string& observable, const std::string& material,
                             const calibrate::Condition& conditions,
                             std::string* error) const;
};

// "simulated:<engine>" with a well-formed engine name (1 to 40 of a-z, 0-9, '.', '-', '_'); the
// engine in *engine when given.
bool IsSimulatedProvenance(const std::string& provenance, std::string* engine = nullptr);
// Made by a model, not measured: synthetic (demcal) or simulated by another engine. A fit to
// such rows says nothing about a real powder; reports badge them.
bool IsModelMadeProvenance(const std::string& provenance);

bool LoadMeasurementTable(const std::string& path, MeasurementTable* out, std::string* error);

}  // namespace demcal::workflow
