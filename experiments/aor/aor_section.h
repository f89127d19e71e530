#pragma once
// The "aor" section of an experiment file → objectives::AorSettings (docs/experiments/aor.md).
#include <nlohmann/json.hpp>
#include <string>

#include "core/scene/scene.h"
#include "experiments/aor/aor_experiment.h"

namespace demcal::workflow {

// `model` is the particle model at the run's fidelity (sizes checked against the geometry).
// False with "<source>: field ... " on the first problem.
bool ParseAorSection(const nlohmann::json& section, const std::string& source,
                     const core::Scene& model, objectives::AorSettings* settings,
                     std::string* error);

}  // namespace demcal::workflow
