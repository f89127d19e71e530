// demcal_dump_angle DECK_DIR [--conical]: the repose angle of a LIGGGHTS run of an exported
// aor deck (demcal export liggghts), measured by demcal's own slot (or conical) heap fit on
// DECK_DIR/post/final.liggghts. The glued base (the first fixed_particles ids of
// DECK_DIR/export.json) is left out and base_top_m is the angle's base height, as RunAor does.
// Prints "angle_deg A spread_deg S grains N"; exit 1 with a message when it cannot measure.
#include <CLI/CLI.hpp>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>

#include "objectives/metrics/repose_angle.h"
#include "workflow/export/liggghts_dump.h"

int main(int argc, char** argv) {
  using namespace demcal;
  CLI::App app{"repose angle of a LIGGGHTS run of an exported aor deck"};
  std::string dir;
  bool conical = false;
  app.add_option("deck", dir, "the export folder")->required();
  app.add_flag("--conical", conical, "a conical heap (axis x = y = 0)");
  CLI11_PARSE(app, argc, argv);
  std::ifstream manifest_in(dir + "/export.json");
  nlohmann::json manifest;
  try {
    manifest = nlohmann::json::parse(manifest_in);
  } catch (const std::exception& e) {
    std::cerr << "error: " << dir << "/export.json: " << e.what() << "\n";
    return 1;
  }
  objectives::Snapshot snap;
  std::string error;
  if (!workflow::ReadLiggghtsDump(dir + "/post/final.liggghts", &snap, &error)) {
    std::cerr << "error: " << error << "\n";
    return 1;
  }
  const int64_t fixed = manifest.value("fixed_particles", int64_t{0});
  snap = objectives::Select(snap, [&](const objectives::Grain& g) { return g.id > fixed; });
  objectives::ReposeAngleOptions options;
  options.base_z_m = manifest.value("base_top_m", 0.0);
  const objectives::ReposeAngle a =
      conical ? objectives::MeasureConicalHeapAngle(snap, {0, 0, 0}, options)
              : objectives::MeasureSlotHeapAngle(snap, options);
  if (!a.ok) {
    std::cerr << "error: no angle: " << a.message << "\n";
    return 1;
  }
  std::cout << "angle_deg " << a.angle_deg << " spread_deg " << a.spread_deg << " grains "
            << snap.grains.size() << "\n";
  return 0;
}
