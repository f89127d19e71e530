#include "core/insertion/insertion.h"

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
  OccupancyGrid(const Vec3& lo, const Vec3& hi, double cell) : origin_(lo), cell_(cell) {
    for (int a = 0; a < 3; ++a)
      dims_[a] = std::max(1, static_cast<int>(std::ceil((hi[a] - lo[a]) / cell)));
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
      // Clamped as a double first: a far or non-finite position must not overflow the int
      // conversion (undefined behaviour; found by fuzz_checkpoint under UBSan).
      const double f = std::floor((x[a] - origin_[a]) / cell_);
      if (!(f >= 0 && f < dims_[a])) inside = false;
      c[a] = static_cast<int>(std::clamp(std::isnan(f) ? 0.0 : f, 0.0, double(dims_[a] - 1)));
    }
    return inside;
  }
  size_t Index(int x, int y, int z) const { return (static_cast<size_t>(z) * dims_[1] + y) * dims_[0] + x; }

  Vec3 origin_;
  double cell_ = 0;
  int dims_[3] = {};
  std::vector<std::vector<uint32_t>> cells_;
};

}  // namespace

std::vector<double> NumberWeightsFromMassFractions(const std::vector<double>& w,
                                                   const std::vector<double>& mean_mass) {
  std::vector<double> n(w.size());
  for (size_t k = 0; k < w.size(); ++k) n[k] = w[k] / mean_mass[k];
  return n;
}

namespace {
const SpeciesDraw& DrawSpecies(const std::vector<SpeciesDraw>& mixture, Rng& rng) {
  if (mixture.size() == 1) return mixture[0];
  double total = 0;
  for (const SpeciesDraw& d : mixture) total += d.number_weight;
  double u = rng.Uniform() * total;
  for (const SpeciesDraw& d : mixture) {
    if (u < d.number_weight) return d;
    u -= d.number_weight;
  }
  return mixture.back();
}
}  // namespace

InsertionResult InsertRandomNonOverlapping(const InsertionRequest& q, Rng& rng,
                                           ParticleSystem& system) {
  Particles& particles = system.spheres;
  double max_d = 0;
  for (const SpeciesDraw& d : q.mixture)
    max_d = std::max(max_d, 2 * system.EnclosingRadius(d.species, d.size->MaxDiameter()));
  for (double r : particles.radius_m) max_d = std::max(max_d, 2 * r);
  // Grid over the region grown by one diameter so particles already near it are seen too.
  const Vec3 grow{max_d, max_d, max_d};
  OccupancyGrid grid(q.region.min_m - grow, q.region.max_m + grow, max_d);
  for (uint32_t s = 0; s < particles.Size(); ++s) grid.Add(particles.position_m[s], s);

  InsertionResult result;
  while (result.count < q.max_count && result.mass_kg < q.max_mass_kg) {
    const SpeciesDraw& draw = DrawSpecies(q.mixture, rng);
    const double d = draw.size->Sample(rng.Uniform());
    const double r = system.EnclosingRadius(draw.species, d);
    bool placed = false;
    for (int attempt = 0; attempt < q.max_attempts_per_particle && !placed; ++attempt) {
      Vec3 x;
      if (!q.region.Sample(r, rng, &x)) break;
      if (!grid.IsFree(x, r, particles)) continue;
      const Quaternion orientation =
          system.IsClump(draw.species)
              ? UniformRandomOrientation(rng.Uniform(), rng.Uniform(), rng.Uniform())
              : Quaternion{};
      const size_t first = particles.Size();
      const size_t clumps_before = system.clumps.Size();
      system.Add(draw.species, draw.material, draw.density_kg_m3, d, x, q.velocity_m_s, {},
                 orientation);
      for (size_t s = first; s < particles.Size(); ++s) grid.Add(particles.position_m[s], s);
      result.mass_kg += system.clumps.Size() > clumps_before ? system.clumps.mass_kg.back()
                                                              : particles.mass_kg[first];
      ++result.count;
      placed = true;
    }
    if (!placed) {
      result.region_full = true;
      break;
    }
  }
  return result;
}

}  // namespace demcal::core
