#pragma once
// Test helpers for the simulate command: a tiny scene that runs in a fraction of a second, a
// quiet run of a scene, and small file utilities.
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "core/io/scratch_dir.h"
#include "workflow/simulation/simulate.h"

namespace demcal::testing {

// 20 spheres dropped into a closed 20 mm box for 20 ms, snapshots every 5 ms.
inline nlohmann::json TinyScene() {
  return nlohmann::json::parse(R"({
    "format": "demcal-scene/1",
    "seed": 3,
    "materials": [{"name": "glass", "youngs_modulus_Pa": 5e6, "poisson_ratio": 0.25,
                   "density_kg_m3": 2500}],
    "species": [{"name": "beads", "material": "glass", "diameter_m": 0.002}],
    "domain": {"min_m": [0, 0, 0], "max_m": [0.02, 0.02, 0.02]},
    "walls": [{"type": "box", "min_m": [0, 0, 0], "max_m": [0.02, 0.02, 0.02],
               "material": "glass"}],
    "fills": [{"species": "beads", "count": 20,
               "region": {"min_m": [0.001, 0.001, 0.001], "max_m": [0.019, 0.019, 0.019]}}],
    "time": {"duration_s": 0.02},
    "output": {"vtk_interval_s": 0.005, "vtk_format": "ascii"}
  })");
}

// Writes `scene` to DIR/<name> and returns the path.
inline std::string WriteScene(const ScratchDir& dir, const nlohmann::json& scene,
                              const std::string& name = "scene.json") {
  const std::string path = dir.str(name);
  std::ofstream(path) << scene.dump(2);
  return path;
}

// Writes `scene` to DIR/scene.json and runs `demcal simulate` on it quietly into DIR/out with
// `threads` (0: all cores); the exit code, and what the run printed into *log when given.
inline int SimulateQuietly(const ScratchDir& dir, const nlohmann::json& scene, int threads = 0,
                           std::string* log = nullptr) {
  workflow::SimulateOptions o;
  o.scene_path = WriteScene(dir, scene);
  o.out_dir = dir.str("out");
  o.threads = threads;
  o.quiet = true;
  std::ostringstream text;
  const int code = workflow::RunSimulate(o, text);
  if (log) *log = text.str();
  return code;
}

inline nlohmann::json ReadJson(const std::string& path) {
  return nlohmann::json::parse(std::ifstream(path));
}

inline std::string ReadFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace demcal::testing
