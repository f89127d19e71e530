#pragma once
// The starting point of every experiment's scene: the particle model (materials, species, pair
// table, contact model, time settings) with the run's seed and wall-time budget, and no walls,
// particles, fills or factories yet.
#include <cstdint>

#include "core/scene/scene.h"

namespace demcal::objectives {

inline core::Scene EmptyExperimentScene(const core::Scene& model, uint64_t seed,
                                        double max_wall_time_s) {
  core::Scene scene = model;
  scene.seed = seed;
  scene.max_wall_time_s = max_wall_time_s;
  scene.walls.clear();
  scene.particles.clear();
  scene.fills.clear();
  scene.factories.clear();
  return scene;
}

}  // namespace demcal::objectives
