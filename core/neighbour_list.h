#pragma once
// NeighbourList: a Verlet list built with a cell grid. It holds every pair i < j whose surfaces
// are closer than `skin` (|x_i − x_j| < R_i + R_j + skin), as a half list in compressed rows
// (row i lists its partners j > i in ascending order), plus the reverse index (for each j, the
// entries that name it) so forces can be gathered per particle in a fixed order: the result is
// then bit-identical for any thread count.
//
// Fixed spheres (glued, never moving) occupy the slots from `first_fixed` on: pairs among them
// are left out (LIGGGHTS: neigh_modify exclude type), so their rows are empty and only moving
// particles are searched; a moving–fixed pair is listed in the moving particle's row.
//
// The list stays valid until some moving particle has moved more than skin/2 since the build
// (NeedsRebuild). Thread-safety: Build() uses TBB internally; const methods are thread-safe.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/periodic_box.h"
#include "core/vec3.h"

namespace demcal::core {

class NeighbourList {
 public:
  struct Settings {
    Vec3 domain_min_m, domain_max_m;  // the grid never extends beyond; outliers are clamped
    double skin_m = 0;
    double max_radius_m = 0;
    PeriodicBox periodic;  // periodic axes: the grid spans the domain and wraps around
  };

  // `body` (optional): spheres with the same non-negative body index (members of one clump)
  // are never paired. Slots from `first_fixed` on are fixed spheres (clamped to the count).
  void Build(const Settings& settings, const std::vector<Vec3>& positions,
             const std::vector<double>& radii, const std::vector<int>* body = nullptr,
             size_t first_fixed = SIZE_MAX);
  bool NeedsRebuild(const std::vector<Vec3>& positions) const;
  // NeedsRebuild for periodic boxes: displacements by minimum image (a wrap is not a move).
  bool NeedsRebuild(const std::vector<Vec3>& positions, const PeriodicBox& box) const;

  size_t RowsCount() const { return row_start_.size() - 1; }
  // First fixed slot of the last build (RowsCount() if none): rows from here on are empty.
  uint32_t FirstFixed() const { return first_fixed_; }
  size_t PairCount() const { return partner_.size(); }
  uint32_t RowBegin(size_t i) const { return row_start_[i]; }
  uint32_t RowEnd(size_t i) const { return row_start_[i + 1]; }
  uint32_t Partner(size_t k) const { return partner_[k]; }
  uint32_t ReverseBegin(size_t j) const { return reverse_start_[j]; }
  uint32_t ReverseEnd(size_t j) const { return reverse_start_[j + 1]; }
  uint32_t ReverseEntry(size_t r) const { return reverse_entry_[r]; }
  // Entry index of pair (i, j) with i < j, or -1 if the pair is not listed.
  int64_t Find(uint32_t i, uint32_t j) const;

  // Particle slots ordered by cell (a locality-friendly order for Particles::Permute).
  std::vector<uint32_t> CellOrder(const Settings& settings, const std::vector<Vec3>& positions) const;

  uint64_t Builds() const { return builds_; }

  // Checkpointing: the list and its rebuild reference (cell scratch is rebuilt on demand).
  template <class A>
  void Serialize(A& a) {
    a.Vector(row_start_), a.Vector(partner_), a.Vector(reverse_start_), a.Vector(reverse_entry_);
    a.Vector(reference_position_), a.Value(half_skin2_), a.Value(builds_), a.Value(first_fixed_);
  }

 private:
  struct Grid {
    Vec3 origin;
    Vec3 inv_cell;  // per axis: cells are at least the cut-off and tile the spanned box
    int nx, ny, nz;
    bool wrap[3];   // periodic axis: neighbour cells wrap around
    Vec3 reach_lo, reach_hi;  // moving particles' box grown by a cut-off: fixed partners inside
    int CellOf(const Vec3& x) const;
  };
  // Over the first `moving` slots (the rest are fixed spheres).
  Grid MakeGrid(const Settings& s, const std::vector<Vec3>& positions, size_t moving) const;
  // Fixed spheres out of reach of every moving particle are not binned (cell −1).
  void BinParticles(const Grid& grid, const std::vector<Vec3>& positions, size_t moving);
  template <class Visit>
  void ForEachCandidate(const Grid& grid, size_t i, const std::vector<Vec3>& x,
                        const std::vector<double>& r, const std::vector<int>* body, double skin,
                        Visit&& visit) const;

  std::vector<uint32_t> row_start_{0};
  std::vector<uint32_t> partner_;
  std::vector<uint32_t> reverse_start_{0};
  std::vector<uint32_t> reverse_entry_;
  std::vector<Vec3> reference_position_;
  PeriodicBox periodic_;
  double half_skin2_ = 0;
  uint64_t builds_ = 0;
  uint32_t first_fixed_ = 0;
  // cell binning scratch (reused between builds)
  std::vector<int> cell_of_particle_;
  std::vector<uint32_t> cell_start_;
  std::vector<uint32_t> cell_particles_;
  // Rows found in one search: up to row_capacity_ partners per particle, sized from the last
  // build's longest row; a row that overflows sends the build to a count-then-fill search.
  bool SearchOnce(const Grid& grid, const Settings& s, const std::vector<Vec3>& x,
                  const std::vector<double>& r, const std::vector<int>* body);
  std::vector<uint32_t> row_scratch_;
  uint32_t row_capacity_ = 32;
};

}  // namespace demcal::core
