#pragma once
// What an exported deck runs: the scene one replicate of an experiment file builds at a
// fidelity, with how the run ends. Today the aor experiment is exported (its scene, its feed
// and its kinetic-energy settle criterion); discharge and segregation drive their runs from
// code between steps (a gate opened once the fill has settled, granule tracking) that a deck
// cannot say, and are refused with that reason.
//
//   ExportRun run;
//   if (!ExportRunOf(file, fidelity, &run, &error)) ...;
#include <string>

#include "core/scene/scene.h"
#include "experiments/common/experiment_file.h"
#include "nlohmann/json.hpp"
#include "objectives/common/fidelity.h"
#include "objectives/common/settled_run.h"

namespace demcal::workflow {

struct ExportRun {
  core::Scene scene;    // at the fidelity, for the file's seed
  bool settle = false;  // run to settle.feed_end_s + min_settle_s, then until settled
  objectives::SettleCriteria settle_criteria;
  double base_top_m = 0;  // top of a glued base (the angle's reference height), 0 if none
};

bool ExportRunOf(const ExperimentFile& file, const objectives::Fidelity& fidelity, ExportRun* out,
                 std::string* error);

// Applies a calibration's "demcal-params/1" file (its "interactions_pairs": materials and
// property values) to `model`; false with *error naming the file and the field.
bool ApplyCalibratedParams(const nlohmann::json& params, const std::string& source,
                           core::Scene* model, std::string* error);

}  // namespace demcal::workflow
