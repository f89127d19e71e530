#pragma once
// The paper's Fig. 3 as stage 1 records it: per clump sphere count of a species, the simulated
// repose angle ± its standard error, the calibration cost (Σ standardised residual²) and whether
// the count matches the measured angle within noise. Read from a clump-count calibration's own
// outputs (clump_count.json and clumps_<n>/result.json, docs/calibration.md), so the table is
// the calibration's record, not a second computation; and drawn as a report table.
#include <nlohmann/json.hpp>
#include <string>

#include "outputs/html_report.h"

namespace demcal::workflow {

// {"rows": [{"count", "angle_deg", "angle_sem_deg", "cost", "within_noise", "agrees",
// "termination"}] in the loop's order, "note": the loop's verdict in words}; a missing or
// unreadable file leaves its numbers null (no rows without clump_count.json). `dir` is the
// calibration's output folder.
nlohmann::json ReadClumpCountTable(const std::string& dir);

// The row of the count with the least cost (null: no row has one). When no count matches, the
// later stages still need a grain: the nearest one, named as such.
nlohmann::json NearestClumpRow(const nlohmann::json& rows);

// The table of one species (`entry`: stage 1's species entry with its "clump_table"), with the
// count chosen and the note of the loop; nothing when the entry has no table. Rows with an
// "aspect_ratio" (a search that calibrated it per count, shape_search.h) add the calibrated
// aspect ratio ± σ, the heaps and wall time each count cost and a note per row.
bool AddClumpCountTable(const std::string& species, const nlohmann::json& entry, HtmlReport* r,
                        std::string* error);

}  // namespace demcal::workflow
