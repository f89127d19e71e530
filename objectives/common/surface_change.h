#pragma once
// SurfaceGrid: the free surface of the moving grains as the top (z + R) of the highest moving
// sphere in each square cell of a horizontal grid, and how much it changed between two times.
// Used by RunUntilSettled's scale-free criterion "the heap profile no longer changes"
// (settled_run.h). Fixed spheres are left out (a glued base never changes).
#include <cstdint>
#include <utility>
#include <vector>

#include "core/simulation/simulation.h"

namespace demcal::objectives {

struct SurfaceGrid {
  double cell_m = 0;
  std::vector<std::pair<int64_t, double>> tops;  // (cell key, top z + R), sorted by key
};

// The surface of the moving spheres (free ones and clump members) on cells of cell_m.
SurfaceGrid MovingSurface(const core::Simulation& sim, double cell_m);

// Mean over the cells of either grid of |top_a − top_b|; a cell in only one grid counts
// `missing_m` (a grain arrived or left). 0 when both are empty.
double MeanSurfaceChange(const SurfaceGrid& a, const SurfaceGrid& b, double missing_m);

// Mean diameter of the moving spheres (m); 0 without any.
double MeanMovingDiameter(const core::Simulation& sim);

}  // namespace demcal::objectives
