#include "objectives/metrics/surface_profile.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>

namespace demcal::objectives {

namespace {

using CellKey = std::pair<long long, long long>;

// The highest candidate per cell, sorted by s. A map keeps memory proportional to the occupied
// cells, whatever the cell size.
class HighestPerCell {
 public:
  void Offer(const CellKey& cell, const SurfacePoint& candidate) {
    auto [it, inserted] = highest_.try_emplace(cell, candidate);
    if (!inserted && candidate.top_m > it->second.top_m) it->second = candidate;
  }
  std::vector<SurfacePoint> Profile() const {
    std::vector<SurfacePoint> profile;
    for (const auto& [cell, p] : highest_) profile.push_back(p);
    std::sort(profile.begin(), profile.end(),
              [](const SurfacePoint& a, const SurfacePoint& b) { return a.s_m < b.s_m; });
    return profile;
  }

 private:
  std::map<CellKey, SurfacePoint> highest_;
};

// Cell index of a non-negative coordinate; false for a coordinate outside any sensible grid.
bool CellIndex(double offset_m, double cell_m, long long* index) {
  const double k = std::floor(offset_m / cell_m);
  if (!(k >= 0 && k < 1e15)) return false;
  *index = static_cast<long long>(k);
  return true;
}

}  // namespace

std::vector<SurfacePoint> SlotProfile(const Snapshot& snapshot, double cell_m) {
  double x_min = INFINITY;
  for (const SurfaceSphere& sphere : snapshot.spheres) x_min = std::min(x_min, sphere.position_m.x);
  HighestPerCell cells;
  for (const SurfaceSphere& sphere : snapshot.spheres) {
    long long k = 0;
    if (CellIndex(sphere.position_m.x - x_min, cell_m, &k))
      cells.Offer({k, 0}, {sphere.position_m.x, sphere.position_m.z + sphere.radius_m});
  }
  return cells.Profile();
}

std::vector<std::vector<SurfacePoint>> SectorProfiles(const Snapshot& snapshot, Vec3 axis_point_m,
                                                      int sectors, double cell_m) {
  const double sector_rad = 2 * std::numbers::pi / sectors;
  std::vector<HighestPerCell> cells(sectors);
  for (const SurfaceSphere& sphere : snapshot.spheres) {
    const double dx = sphere.position_m.x - axis_point_m.x;
    const double dy = sphere.position_m.y - axis_point_m.y;
    const double r = std::hypot(dx, dy);
    double azimuth = std::atan2(dy, dx);
    if (azimuth < 0) azimuth += 2 * std::numbers::pi;
    const int sector = std::min(sectors - 1, static_cast<int>(azimuth / sector_rad));
    long long ring = 0;
    if (!CellIndex(r, cell_m, &ring)) continue;
    // Rings split into arcs about one cell long, so every cell holds about as many spheres and
    // the per-cell maximum is not biased upwards far from the axis (where a sector is wider).
    const double arcs = std::max(1.0, std::floor(sector_rad * (static_cast<double>(ring) + 0.5)));
    const double within = std::clamp(azimuth / sector_rad - sector, 0.0, 1.0 - 1e-12);
    cells[sector].Offer({ring, static_cast<long long>(within * arcs)},
                        {r, sphere.position_m.z + sphere.radius_m});
  }
  std::vector<std::vector<SurfacePoint>> profiles;
  for (const HighestPerCell& sector : cells) profiles.push_back(sector.Profile());
  return profiles;
}

int ApexIndex(const std::vector<SurfacePoint>& profile) {
  const int n = static_cast<int>(profile.size());
  if (n == 0) return -1;
  int smooth_best = 0;
  double smooth_max = -INFINITY;
  for (int i = 0; i < n; ++i) {
    const int lo = std::max(0, i - 1), hi = std::min(n - 1, i + 1);
    double sum = 0;
    for (int j = lo; j <= hi; ++j) sum += profile[j].top_m;
    const double mean = sum / (hi - lo + 1);
    if (mean > smooth_max) {
      smooth_max = mean;
      smooth_best = i;
    }
  }
  int best = smooth_best;
  for (int j = std::max(0, smooth_best - 1); j <= std::min(n - 1, smooth_best + 1); ++j)
    if (profile[j].top_m > profile[best].top_m) best = j;
  return best;
}

}  // namespace demcal::objectives
