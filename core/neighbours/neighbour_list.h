#pragma once
// NeighbourList: a Verlet list built with a cell grid. It holds every pair i < j whose surfaces
// are closer than `skin` (|x_i − x_j| < R_i + R_j + skin), as a half list in compressed rows
// (row i lists its partners j > i in ascending order). The force sweep visits the entries in
// this fixed order whatever the thread count (core/neighbours/sweep_chunks.h), so results are
// bit-identical for any number of threads.
//
// Fixed spheres (glued, never moving) occupy the slots from `first_fixed` on: pairs among them
// are left out (LIGGGHTS: neigh_modify exclude type), so their rows are empty and only moving
// particles are searched; a moving–fixed pair is listed in the moving particle's row.
//
// Each particle has a reference position (where it was when its neighbourhood was last searched);
// the list holds exactly the pairs with |p_i − p_j| < R_i + R_j + skin over reference positions
// p, and it stays valid until some moving particle is more than skin/2 from its reference
// (NeedsRebuild). Build() sets every reference to the current position and searches all moving
// particles; Update() (the incremental rebuild) moves the references of the particles that
// moved more than `refresh_fraction` × skin only ("movers"), searches around those, and keeps
// the rows of the others: its cost follows what moved. The result depends on the positions
// alone, never on the thread count. Thread-safety: Build()/Update() use TBB internally; const
// methods are thread-safe.
//
// Usage (as Simulation does; `old` is the list of the previous build):
//   if (old.NeedsRebuild(x)) list.Update(settings, x, r, nullptr, first_fixed, old, 0.25);
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "core/math/heap_bytes.h"
#include "core/math/periodic_box.h"
#include "core/math/vec3.h"

namespace demcal::core {

class NeighbourList {
 public:
  struct Settings {
    Vec3 domain_min_m, domain_max_m;  // the grid never extends beyond; outliers are clamped
    double skin_m = 0;
    double max_radius_m = 0;
    PeriodicBox periodic;  // periodic axes: the grid spans the domain and wraps around
  };
  // At most this many cells per binned particle (and at least 4,096 cells in all): beyond, the
  // cells are enlarged (MakeGrid). A packed bed has ≈ 0.7 cells per particle, a pour's column
  // over a wide base tens (cell_order_test: 48); a far-flung particle (clamped into a large
  // domain) makes the grid span the domain, which at a cut-off per cell could ask billions of
  // cells (an int overflow and gigabytes of cell starts) and pass over all of them at every
  // rebuild. Larger cells add candidates (the list is the same) and change the re-sort's order,
  // so the cap sits above any geometry a run holds together: 256 B of cell starts per particle.
  static constexpr double kMaxCellsPerParticle = 64;

  // `body` (optional): spheres with the same non-negative body index (members of one clump)
  // are never paired. Slots from `first_fixed` on are fixed spheres (clamped to the count).
  void Build(const Settings& settings, const std::vector<Vec3>& positions,
             const std::vector<double>& radii, const std::vector<int>* body = nullptr,
             size_t first_fixed = SIZE_MAX);
  // Incremental rebuild from `previous` (the last build over the same slots): particles more
  // than refresh_fraction × skin (in (0, 0.5]) from their reference are re-searched, the rows
  // of the others are kept. Falls back to Build() when the slots changed (count, first fixed
  // slot, settings) or more than half the moving particles moved. `previous` is not modified.
  void Update(const Settings& settings, const std::vector<Vec3>& positions,
              const std::vector<double>& radii, const std::vector<int>* body, size_t first_fixed,
              const NeighbourList& previous, double refresh_fraction);
  // This list becomes `previous` with its slots compacted: new slot s is old slot order[s]
  // (strictly ascending: a sink's removal), the removed slots' rows and entries dropped, the
  // references kept; it is then Update()'s `previous` after a removal, so that a removal costs an
  // incremental rebuild, not a full one. Rows only (build count unchanged).
  // False (and nothing usable) if `order` is not such a compaction of `previous`, or if slots
  // below `first_fixed` were not all moving ones and those above all fixed; then Build().
  bool CompactFrom(const NeighbourList& previous, const std::vector<uint32_t>& order,
                   size_t first_fixed);
  // Particles re-searched by the last build (all moving ones after Build()).
  size_t LastMovers() const { return last_movers_; }
  // Where particle i was when its neighbourhood was last searched.
  const Vec3& ReferencePosition(size_t i) const { return reference_position_[i]; }
  const std::vector<Vec3>& ReferencePositions() const { return reference_position_; }
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
  // Entry index of pair (i, j) with i < j, or -1 if the pair is not listed.
  int64_t Find(uint32_t i, uint32_t j) const;

  // Particle slots ordered by cell (a locality-friendly order for Particles::Permute).
  // swept[i]: whether the force sweep visits slot i (not a fixed sphere it skips); empty: every
  // slot. Only swept spheres count towards the size of a plane of cells (the .cc says why).
  std::vector<uint32_t> CellOrder(const Settings& settings, const std::vector<Vec3>& positions,
                                  const std::vector<uint8_t>& swept = {}) const;

  uint64_t Builds() const { return builds_; }
  // The list's arrays and its search scratch (core/math/heap_bytes.h).
  HeapBytes Heap() const {
    return {VectorBytes(row_start_, reference_position_, cell_of_particle_,
                        cell_particles_, row_scratch_, is_mover_, new_slot_, movers_) +
                VectorBytes(found_, found_count_, incoming_start_),
            VectorBytes(partner_, incoming_) + BlockBytes(), VectorBytes(cell_start_, fixed_rows_)};
  }

  // Checkpointing: the list and its rebuild reference (cell scratch is rebuilt on demand).
  template <class A>
  void Serialize(A& a) {
    a.Vector(row_start_), a.Vector(partner_);
    a.Vector(reference_position_), a.Value(half_skin2_), a.Value(builds_), a.Value(first_fixed_);
  }

  // After a checkpoint load: rows, partners and references fit `particles` and
  // the scene's skin; false with the failed check (core/checkpoint/checkpoint_checks_contacts.cc).
  bool CheckRestored(size_t particles, double skin_m, std::string* error) const;

 private:
  struct Grid {
    Vec3 origin;
    Vec3 inv_cell;  // per axis: cells are at least the cut-off and tile the spanned box
    int nx = 0, ny = 0, nz = 0;
    bool wrap[3] = {};  // periodic axis: neighbour cells wrap around
    Vec3 reach_lo, reach_hi;  // moving particles' box grown by a cut-off: fixed partners inside
    int CellOf(const Vec3& x) const;
  };
  // Over the first `moving` slots (the rest are fixed spheres).
  Grid MakeGrid(const Settings& s, const std::vector<Vec3>& positions, size_t moving) const;
  // Over the box [lo, hi] (grown by a cut-off and binning others within reach if asked), for
  // about `particles` binned particles.
  Grid MakeGrid(const Settings& s, Vec3 lo, Vec3 hi, bool margin_for_others,
                size_t particles) const;
  // Rebuild reference and count, after the rows are filled.
  void Finish(const Settings& s);
  // Fixed spheres out of reach of every moving particle are not binned (cell −1).
  void BinParticles(const Grid& grid, const std::vector<Vec3>& positions, size_t moving);
  template <bool kUpperOnly, class Visit>
  void ForEachCandidate(const Grid& grid, size_t i, const std::vector<Vec3>& x,
                        const std::vector<double>& r, const std::vector<int>* body, double skin,
                        Visit&& visit) const;
  // Each moving pair from one side only; grids with no periodic axis (neighbour_list_search.h).
  template <class Visit>
  void ForEachForwardCandidate(const Grid& grid, size_t i, const std::vector<Vec3>& x,
                               const std::vector<double>& r, const std::vector<int>* body,
                               double skin, Visit&& visit) const;

  std::vector<uint32_t> row_start_{0};
  std::vector<uint32_t> partner_;
  std::vector<Vec3> reference_position_;
  PeriodicBox periodic_;
  double half_skin2_ = 0;
  uint64_t builds_ = 0;
  uint32_t first_fixed_ = 0;
  // cell binning scratch (reused between builds)
  std::vector<int> cell_of_particle_;
  std::vector<uint32_t> cell_start_;
  std::vector<uint32_t> cell_particles_;  // then kGatherRun spare entries (ForEachForwardCandidate)
  static constexpr uint32_t kGatherRun = 16;
  std::vector<uint8_t> fixed_rows_;  // per row of cells (z, y): holds a binned fixed sphere
  // Periodic grids: rows found in one search, up to row_capacity_ partners per particle, sized
  // from the last build's longest row; a row that overflows sends the build to a count-then-fill
  // search.
  bool SearchOnce(const Grid& grid, const Settings& s, const std::vector<Vec3>& x,
                  const std::vector<double>& r, const std::vector<int>* body);
  // The rows of a build on a grid with no periodic axis: the half-stencil search, each pair
  // listed in its lower slot's row (neighbour_list.cc).
  void SearchForward(const Grid& grid, const Settings& s, const std::vector<Vec3>& x,
                     const std::vector<double>& r, const std::vector<int>* body);
  void MarkFixedRows(const Grid& grid);
  static constexpr size_t kSearchBlock = 2048;  // particles per buffer of SearchForward
  std::vector<std::vector<uint32_t>> block_found_;
  size_t BlockBytes() const {
    size_t bytes = VectorBytes(block_found_);
    for (const auto& b : block_found_) bytes += VectorBytes(b);
    return bytes;
  }
  std::vector<uint32_t> row_scratch_;
  uint32_t row_capacity_ = 32;
  // Update() scratch: movers, their partners on both sides, partners gained by kept rows.
  std::vector<uint8_t> is_mover_;
  std::vector<uint32_t> new_slot_;  // CompactFrom() scratch
  std::vector<uint32_t> movers_, found_, found_count_, incoming_start_, incoming_;
  uint32_t found_capacity_ = 64;
  size_t last_movers_ = 0;
};

}  // namespace demcal::core
