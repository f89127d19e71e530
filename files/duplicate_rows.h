#pragma once
// FirstDuplicateRow: the first pair of measurement rows with the same observable, material and
// conditions (cells compared as calibrate::SameConditionCell does: numbers to 1e-12 relative,
// words exactly), found in O(n log n) rather than by comparing every row with every earlier one.
// "First" is the pair a line-by-line check reports: the earliest later row that repeats an
// earlier one, and the earliest row it repeats.
//
// Thread-safety: a pure function.
#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

#include "files/measurement_table.h"

namespace demcal::workflow {

// True when the two rows have the same observable, material and conditions.
bool SameRowKey(const MeasurementRow& earlier, const MeasurementRow& later);

// (earlier, later) indices into `rows`, or nothing when every row is distinct.
std::optional<std::pair<size_t, size_t>> FirstDuplicateRow(const std::vector<MeasurementRow>& rows);

}  // namespace demcal::workflow
