#pragma once
// The "segregation" section of an experiment file → objectives::SegregationSettings
// (docs/experiments/segregation.md).
#include <nlohmann/json.hpp>
#include <string>

#include "core/scene/scene.h"
#include "experiments/segregation/segregation_experiment.h"

namespace demcal::workflow {

// `model` is the particle model at the run's fidelity (sizes checked against the geometry).
// False with "<source>: field ... " naming the first offending field.
bool ParseSegregationSection(const nlohmann::json& section, const std::string& source,
                             const core::Scene& model, objectives::SegregationSettings* settings,
                             std::string* error);

}  // namespace demcal::workflow
