#pragma once
// result.json of `demcal experiment segregation`: per species the segregation indices as mean and
// standard error over the replicates that succeeded, the mixture angle, the funnel discharge time,
// the tracked granules, and one entry per run. Bases follow the paper: the 2D (face) indices use
// number fractions (image analysis counts granules), the 3D ones mass fractions (section 3.2);
// DIR/segregation_indices_r<k>.csv holds both bases for every region.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "experiments/segregation/segregation_experiment.h"

namespace demcal::workflow {

// Everything after ResultHeader; `runs` in replicate order.
nlohmann::ordered_json SegregationResultJson(const objectives::SegregationSettings& settings,
                                             const std::vector<std::string>& species_names,
                                             const std::vector<objectives::SegregationRun>& runs);

}  // namespace demcal::workflow
