#pragma once
// The numbers `demcal reproduce` takes from a segregation run (the SegregationResult of one
// replicate, experiments/segregation/segregation_result.h): per species the CoV, CoV_r and S_n
// of the front and back faces (number basis) and of the whole heap (mass basis), the mixture
// angle, the funnel discharge time and the tracked granules' peak specific kinetic energy at
// impact (Fig. 19); their mean ± sem over a scenario's replicates; and the summary.json values
// of the paper's list.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "experiments/segregation/segregation_result.h"

namespace demcal::workflow {

// A flat object "EP.s_n_3d" -> number (or null), plus "ok", "status", "wall_time_s".
nlohmann::json ExtractSegregationMetrics(const SegregationResult& experiment_result);

// metric -> {"mean", "sem", "n"} over the runs that are ok (sem null for n < 2).
nlohmann::json SummariseSegregationRuns(const std::vector<nlohmann::json>& runs);

// The summary keys (summary_table.h) from the scenarios' summaries ("uncoated", "coated",
// "excessive"); `coated` names the coated species.
nlohmann::json SegregationSummaryValues(const nlohmann::json& scenarios, const std::string& coated);

}  // namespace demcal::workflow
