#include "objectives/common/surface_change.h"

#include <algorithm>
#include <cmath>

namespace demcal::objectives {
namespace {
bool Moving(const core::Particles& p, size_t i) { return p.inv_mass[i] > 0 || p.body[i] >= 0; }
}  // namespace

SurfaceGrid MovingSurface(const core::Simulation& sim, double cell_m) {
  const core::Particles& p = sim.particles();
  std::vector<std::pair<int64_t, double>> all;
  all.reserve(p.Size());
  for (size_t i = 0; i < p.Size(); ++i) {
    if (!Moving(p, i)) continue;
    const core::Vec3& x = p.position_m[i];
    const int64_t cx = static_cast<int64_t>(std::floor(x.x / cell_m));
    const int64_t cy = static_cast<int64_t>(std::floor(x.y / cell_m));
    all.emplace_back((cx << 32) ^ (cy & 0xffffffff), x.z + p.radius_m[i]);
  }
  std::sort(all.begin(), all.end());
  SurfaceGrid grid{cell_m, {}};
  for (const auto& [key, top] : all) {
    if (!grid.tops.empty() && grid.tops.back().first == key)
      grid.tops.back().second = std::max(grid.tops.back().second, top);
    else
      grid.tops.emplace_back(key, top);
  }
  return grid;
}

double MeanSurfaceChange(const SurfaceGrid& a, const SurfaceGrid& b, double missing_m) {
  double sum = 0;
  size_t cells = 0, i = 0, j = 0;
  while (i < a.tops.size() || j < b.tops.size()) {
    ++cells;
    if (j == b.tops.size() || (i < a.tops.size() && a.tops[i].first < b.tops[j].first)) {
      sum += missing_m, ++i;
    } else if (i == a.tops.size() || b.tops[j].first < a.tops[i].first) {
      sum += missing_m, ++j;
    } else {
      sum += std::abs(a.tops[i].second - b.tops[j].second), ++i, ++j;
    }
  }
  return cells ? sum / static_cast<double>(cells) : 0;
}

double MeanMovingDiameter(const core::Simulation& sim) {
  const core::Particles& p = sim.particles();
  double sum = 0;
  size_t n = 0;
  for (size_t i = 0; i < p.Size(); ++i)
    if (Moving(p, i)) sum += 2 * p.radius_m[i], ++n;
  return n ? sum / static_cast<double>(n) : 0;
}

}  // namespace demcal::objectives
