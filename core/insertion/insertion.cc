#include "core/insertion/insertion.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>
#include <vector>

#include "core/math/bounded_cells.h"

namespace demcal::core {
namespace {

// A dense grid of cells of size >= the largest diameter over the region, holding particle slots.
// At most kMaxCellsPerParticle cells per particle it may hold (present and to be placed; 4,096
// at least): beyond, the cells are enlarged. A few particles asked of a region many thousand
// diameters wide would otherwise ask a cell per diameter cubed, terabytes (larger cells only
// make IsFree look at more particles, never miss one).
class OccupancyGrid {
 public:
  static constexpr double kMaxCellsPerParticle = 16;
  OccupancyGrid(const Vec3& lo, const Vec3& hi, double cell, double particles) : origin_(lo) {
    const double max_cells = std::min(1e8, std::max(4096.0, kMaxCellsPerParticle * particles));
    cell_ = CellForAtMost(hi - lo, cell, max_cells, CellRounding::kUp);
    for (int a = 0; a < 3; ++a)
      dims_[a] = static_cast<int>(CellsAlong(hi[a] - lo[a], cell_, CellRounding::kUp));
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

double DrawMassKg(const ParticleSystem& system, const SpeciesDraw& draw, double d) {
  const double unit_mass = system.IsClump(draw.species)
                               ? system.shapes[draw.species].mass_kg  // as Clumps::Add
                               : std::numbers::pi / 6;
  return unit_mass * draw.density_kg_m3 * d * d * d;
}

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

namespace {
// Diameter of the largest sphere a particle of `draw` adds: the particle itself, or a clump's
// largest member at the largest size.
double LargestMemberDiameter(const ParticleSystem& system, const SpeciesDraw& draw) {
  const double d = draw.size->MaxDiameter();
  if (!system.IsClump(draw.species)) return d;
  double r = 0;
  for (const ClumpSphere& s : system.shapes[draw.species].spheres) r = std::max(r, s.radius_m);
  return 2 * r * d;
}

// Whether a clump of `species`, diameter d, at x with `orientation` overlaps no stored sphere:
// its members are tested, not its enclosing sphere. An elongated clump's enclosing sphere holds
// several times its volume (≈ 9× for a 3:1 four-sphere chain), and testing it against the
// members already placed saturated the region at a fraction of the rate a feed asks for
// (docs/experiments/segregation_angle.md).
bool ClumpIsFree(const OccupancyGrid& grid, const ParticleSystem& system, int species, double d,
                 const Vec3& x, const Quaternion& orientation) {
  for (const ClumpSphere& s : system.shapes[species].spheres)
    if (!grid.IsFree(x + Rotate(orientation, s.centre_m * d), s.radius_m * d, system.spheres))
      return false;
  return true;
}

// One particle to place: its species (and its index in the request's mixture), (equivalent)
// diameter and enclosing radius.
struct Draw {
  const SpeciesDraw* species = nullptr;
  int64_t mixture_index = 0;
  double d = 0, r = 0;
};

Draw DrawParticle(const InsertionRequest& q, Rng& rng, const ParticleSystem& system) {
  const SpeciesDraw& species = DrawSpecies(q.mixture, rng);
  const double d = species.size->Sample(rng.Uniform());
  return {&species, &species - q.mixture.data(), d, system.EnclosingRadius(species.species, d)};
}

// A batch of a given mass that holds clumps is drawn whole, then placed largest enclosing sphere
// first. Drawn and placed in turn, a large clump that came late found the region crowded by the
// small ones before it and ended the batch unplaced, so the stream lost the large species (the
// segregation feed at size ×5: TAED 3.3 % of the mass poured instead of 5.5 %). Placed first,
// it finds the room. The draws carried from earlier batches join the batch before the new ones
// (so among equal sizes the older goes first) and are sorted with them: largest first is the
// order that fits the most into the emptied region, and a carried draw placed ahead of larger
// new ones would crowd them out in turn. Sphere batches keep their draw-and-place order (and
// their random streams): their sizes fit the region's room.
std::vector<Draw> DrawBatchLargestFirst(const InsertionRequest& q, Rng& rng,
                                        const ParticleSystem& system) {
  std::vector<Draw> batch;
  double mass = 0;
  for (const CarriedDraw& c : q.carried) {
    const SpeciesDraw& species = q.mixture[c.mixture_index];
    batch.push_back({&species, c.mixture_index, c.diameter_m,
                     system.EnclosingRadius(species.species, c.diameter_m)});
    mass += DrawMassKg(system, species, c.diameter_m);
  }
  while (static_cast<int64_t>(batch.size()) < q.max_count && mass < q.max_mass_kg) {
    const Draw p = DrawParticle(q, rng, system);
    mass += DrawMassKg(system, *p.species, p.d);
    batch.push_back(p);
  }
  std::stable_sort(batch.begin(), batch.end(),
                   [](const Draw& a, const Draw& b) { return a.r > b.r; });
  return batch;
}

bool HasClump(const InsertionRequest& q, const ParticleSystem& system) {
  for (const SpeciesDraw& d : q.mixture)
    if (system.IsClump(d.species)) return true;
  return false;
}

// The most bodies a request can place: its count, or its mass over the lightest body it can draw
// (a request bounded by neither fills its region, and that many bodies need that many cells).
double MostBodies(const InsertionRequest& q, const ParticleSystem& system) {
  double lightest = std::numeric_limits<double>::infinity();
  for (const SpeciesDraw& d : q.mixture)
    lightest = std::min(lightest, DrawMassKg(system, d, d.size->MinDiameter()));
  const double by_mass = q.max_mass_kg / lightest + static_cast<double>(q.carried.size());
  return std::min(static_cast<double>(q.max_count), std::isfinite(by_mass) ? by_mass : 1e9);
}

}  // namespace

InsertionResult InsertRandomNonOverlapping(const InsertionRequest& q, Rng& rng,
                                           ParticleSystem& system) {
  Particles& particles = system.spheres;
  // Cells as wide as the largest sphere (new member or present): two spheres that touch are in
  // neighbouring cells.
  double max_d = 0;
  for (const SpeciesDraw& d : q.mixture) max_d = std::max(max_d, LargestMemberDiameter(system, d));
  for (double r : particles.radius_m) max_d = std::max(max_d, 2 * r);
  // Grid over the region grown by one diameter so particles already near it are seen too.
  const Vec3 grow{max_d, max_d, max_d};
  OccupancyGrid grid(q.region.min_m - grow, q.region.max_m + grow, max_d,
                     static_cast<double>(particles.Size()) + MostBodies(q, system));
  for (uint32_t s = 0; s < particles.Size(); ++s) grid.Add(particles.position_m[s], s);

  InsertionResult result;
  // A batch of given mass with clumps: drawn first (with the carried draws), every draw tried
  // once, largest first (DrawBatchLargestFirst); those that find no room are returned. A
  // smaller draw may still fit where a larger one found no room, so a failure does not end it.
  const bool largest_first = std::isfinite(q.max_mass_kg) && HasClump(q, system);
  const std::vector<Draw> batch = largest_first ? DrawBatchLargestFirst(q, rng, system)
                                                : std::vector<Draw>{};
  size_t next = 0;
  while (largest_first ? next < batch.size()
                       : result.count < q.max_count && result.mass_kg < q.max_mass_kg) {
    const Draw p = largest_first ? batch[next++] : DrawParticle(q, rng, system);
    const SpeciesDraw& draw = *p.species;
    const double d = p.d, r = p.r;
    bool placed = false;
    for (int attempt = 0; attempt < q.max_attempts_per_particle && !placed; ++attempt) {
      Vec3 x;
      if (!q.region.Sample(r, rng, &x)) break;  // the enclosing sphere inside the region
      Quaternion orientation;
      if (!system.IsClump(draw.species)) {
        if (!grid.IsFree(x, r, particles)) continue;
      } else {
        orientation = UniformRandomOrientation(rng.Uniform(), rng.Uniform(), rng.Uniform());
        if (!ClumpIsFree(grid, system, draw.species, d, x, orientation)) continue;
      }
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
      if (!largest_first) break;
      result.unplaced.push_back({p.mixture_index, p.d});
    }
  }
  return result;
}

}  // namespace demcal::core
