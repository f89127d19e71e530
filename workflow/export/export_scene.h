#pragma once
// What an exported deck runs: the scene one replicate of an experiment file builds at a
// fidelity, with how the run ends.
//  - aor: the pour, then until the kinetic-energy settle criterion holds (or max_time_s).
//  - discharge: the fill (poured or placed), settled as aor, or up to gate_open_s; then the
//    gate is taken away (demcal moves it down faster than the grains can follow, the deck
//    removes it: the same opening for the grains) and the run goes on until no grain is left
//    above the orifice plane, or max_discharge_s.
//  - segregation is refused: its outputs need grains tracked between steps (granules, outflow
//    over time) that a deck cannot say.
//
//   ExportRun run;
//   if (!ExportRunOf(file, fidelity, &run, &error)) ...;
#include <nlohmann/json.hpp>
#include <string>

#include "core/scene/scene.h"
#include "experiments/common/experiment_file.h"
#include "objectives/common/fidelity.h"
#include "objectives/common/settled_run.h"

namespace demcal::workflow {

struct ExportRun {
  core::Scene scene;    // at the fidelity, for the file's seed
  bool settle = false;  // run to settle.feed_end_s + min_settle_s, then until settled
  objectives::SettleCriteria settle_criteria;
  double base_top_m = 0;  // top of a glued base (the angle's reference height), 0 if none
  // A wall taken away after the settle stage ("": none): at open_at_s (> 0), else once settled;
  // then the run goes on until no flowing grain has z > empty_above_z_m, or after_open_max_s.
  std::string open_wall;
  double open_at_s = 0;
  double after_open_max_s = 0;
  double empty_above_z_m = 0;
};

bool ExportRunOf(const ExperimentFile& file, const objectives::Fidelity& fidelity, ExportRun* out,
                 std::string* error);

// Applies a calibration's "demcal-params/1" file (its "interactions_pairs": materials and
// property values) to `model`; false with *error naming the file and the field.
bool ApplyCalibratedParams(const nlohmann::json& params, const std::string& source,
                           core::Scene* model, std::string* error);

}  // namespace demcal::workflow
