#pragma once
// Condition: what distinguishes one measurement from another of the same observable and
// material — a coating level, a size cut, a test geometry — as column -> cell of the measurement
// table (files/measurement_table.h). Cells are numbers or words; numbers compare by
// value ("0.5" equals "0.50"). Parameters may apply only under a condition (Γ of EP at 0.5 wt%)
// or follow a covariate of it (Γ(w), parameter_curve.h).
//
//   Condition c = {{"coating_PEG_wt_pct", "2.5"}};
//   ConditionIncludes(c, {{"coating_PEG_wt_pct", "2.50"}});  // true
#include <map>
#include <string>

namespace demcal::calibrate {

using Condition = std::map<std::string, std::string>;

// A finite decimal number, the whole text (hexadecimal, inf and nan are not numbers).
bool ParseConditionNumber(const std::string& text, double* out);
// Numbers by value (relative 1e-12), words exactly.
bool SameConditionCell(const std::string& a, const std::string& b);
// Every entry of `part` is in `condition` with the same cell.
bool ConditionIncludes(const Condition& condition, const Condition& part);
// The covariate as a number; false when absent or a word.
bool ConditionNumber(const Condition& condition, const std::string& column, double* out);
// "coating_PEG_wt_pct=0.5, test=slot" (sorted by column); "" for none.
std::string DescribeCondition(const Condition& condition);

}  // namespace demcal::calibrate
