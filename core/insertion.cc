#include "core/insertion.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>
#include <vector>

namespace demcal::core {
namespace {

// A dense grid of cells of size >= the largest diameter over the region, holding particle slots.
class OccupancyGrid {
 public:
  OccupancyGrid(const BoxRegion& region, double cell) : origin_(region.min_m), cell_(cell) {
    for (int a = 0; a < 3; ++a)
      dims_[a] = std::max(1, static_cast<int>(std::ceil((region.max_m[a] - region.min_m[a]) / cell)));
    cells_.resize(static_cast<size_t>(dims_[0]) * dims_[1] * dims_[2]);
  }
  void Add(const Vec3& x, uint32_t slot) {
    int c[3];
    if (CellOf(x, c)) cells_[Index(c[0], c[1], c[2])].push_back(slot);
  }
  // True if a sphere (x, r) overlaps none of the stored particles.
  bool IsFree(const Vec3& x, double r, const Particles& p) const {
    int c[3];
    CellOf(x, c);
    for (int dz = -1; dz <= 1; ++dz)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const int ix = c[0] + dx, iy = c[1] + dy, iz = c[2] + dz;
          if (ix < 0 || iy < 0 || iz < 0 || ix >= dims_[0] || iy >= dims_[1] || iz >= dims_[2]) continue;
          for (uint32_t s : cells_[Index(ix, iy, iz)]) {
            const double reach = r + p.radius_m[s];
            if (Norm2(x - p.position_m[s]) < reach * reach) return false;
          }
        }
    return true;
  }

 private:
  bool CellOf(const Vec3& x, int c[3]) const {
    bool inside = true;
    for (int a = 0; a < 3; ++a) {
      c[a] = static_cast<int>(std::floor((x[a] - origin_[a]) / cell_));
      if (c[a] < 0 || c[a] >= dims_[a]) inside = false;
      c[a] = std::clamp(c[a], 0, dims_[a] - 1);
    }
    return inside;
  }
  size_t Index(int x, int y, int z) const { return (static_cast<size_t>(z) * dims_[1] + y) * dims_[0] + x; }

  Vec3 origin_;
  double cell_;
  int dims_[3];
  std::vector<std::vector<uint32_t>> cells_;
};

}  // namespace

int64_t InsertRandomNonOverlapping(const InsertionRequest& q, Rng& rng, Particles& particles,
                                   int64_t& next_id, std::string* error) {
  double max_d = q.size->MaxDiameter();
  for (double r : particles.radius_m) max_d = std::max(max_d, 2 * r);
  // Grid over the region grown by one diameter so particles already near it are seen too.
  BoxRegion grown{q.region.min_m - Vec3{max_d, max_d, max_d}, q.region.max_m + Vec3{max_d, max_d, max_d}};
  OccupancyGrid grid(grown, max_d);
  for (uint32_t s = 0; s < particles.Size(); ++s) grid.Add(particles.position_m[s], s);

  int64_t placed = 0;
  for (; placed < q.count; ++placed) {
    const double r = 0.5 * q.size->Sample(rng.Uniform());
    bool done = false;
    for (int attempt = 0; attempt < q.max_attempts_per_particle && !done; ++attempt) {
      Vec3 x;
      for (int a = 0; a < 3; ++a) x[a] = rng.Uniform(q.region.min_m[a] + r, q.region.max_m[a] - r);
      if (!grid.IsFree(x, r, particles)) continue;
      const size_t slot = particles.Add(next_id++, q.species, q.material, r, q.density_kg_m3, x,
                                        q.velocity_m_s, {});
      grid.Add(x, static_cast<uint32_t>(slot));
      done = true;
    }
    if (!done) break;
  }
  if (placed < q.count && error) {
    const Vec3 e = q.region.max_m - q.region.min_m;
    const double fraction = q.count * q.size->MeanVolume() / (e.x * e.y * e.z);
    std::ostringstream os;
    os << "placed only " << placed << " of " << q.count
       << " particles: the region is too small for that count (it would need a solid fraction of "
       << fraction << "; random insertion works up to about 0.3)";
    *error = os.str();
  }
  return placed;
}

}  // namespace demcal::core
