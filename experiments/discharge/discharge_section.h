#pragma once
// The "discharge" section of an experiment file → objectives::DischargeSettings
// (docs/experiments/discharge.md).
#include <nlohmann/json.hpp>
#include <string>

#include "core/scene/scene.h"
#include "experiments/discharge/discharge_experiment.h"

namespace demcal::workflow {

// `model` is the particle model at the run's fidelity (sizes checked against the hopper).
// False with "<source>: discharge.<field> ..." on the first problem.
bool ParseDischargeSection(const nlohmann::json& section, const std::string& source,
                           const core::Scene& model, objectives::DischargeSettings* settings,
                           std::string* error);

}  // namespace demcal::workflow
