#pragma once
// `demcal export liggghts`: an experiment file as a complete LIGGGHTS-PUBLIC 3.8 deck in a
// folder (docs/export.md lists every file):
//   DIR/in.demcal           the input deck (liggghts -in in.demcal, run inside DIR)
//   DIR/particles.data      placed particles (a glued base), when the scene has any
//   DIR/meshes/*.stl        walls that are not LIGGGHTS primitives (funnels, finite cylinders,
//   meshes) DIR/post/               where the deck writes its dumps (dump_*.liggghts,
//   final.liggghts) DIR/export.json         what was exported: source, fidelity, time step,
//   conversions, files
// The deck runs the scene of one replicate (the file's seed) at the chosen fidelity: its
// materials (calibrate/liggghts_export.h), walls (liggghts_walls.h), particles and insertion
// (liggghts_insertion.h), Δt, gravity and run length; a poured experiment runs until its feed
// has ended and the moving grains' mean specific kinetic energy is below the experiment's
// threshold (checked every check_interval_s), or its max_time_s.
// The command around it is run_export.h.
#include <string>
#include <utility>
#include <vector>

#include "calibrate/liggghts_export.h"
#include "workflow/export/export_scene.h"

namespace demcal::workflow {

struct ExportOptions {
  std::string experiment_path;
  std::string params_path;        // calibrated_params.json ("" : the file's own values)
  std::string fidelity = "full";  // full | file | quick
  std::string out_dir;
  calibrate::LiggghtsLawOptions law;
  double dump_interval_s = 0.1;  // simulated time between particle dumps
};

// The deck text of `run` (what in.demcal holds); false with *error when part of the scene
// cannot be written. Fills *files with (relative path, contents) of the other files.
bool LiggghtsDeck(const ExportRun& run, const ExportOptions& options,
                  const std::vector<std::string>& comments, std::string* deck,
                  std::vector<std::pair<std::string, std::string>>* files,
                  nlohmann::ordered_json* summary, std::string* error);

}  // namespace demcal::workflow
