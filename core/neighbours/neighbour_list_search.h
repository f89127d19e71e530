#pragma once
// Internal to the neighbour list (neighbour_list.cc, neighbour_list_update.cc): the cell of a
// point and the candidate searches over the cells around a particle.
#include <algorithm>
#include <cmath>

#include "core/neighbours/neighbour_list.h"

namespace demcal::core {

inline int NeighbourList::Grid::CellOf(const Vec3& x) const {
  // Outliers are clamped into the edge cells, or wrapped on periodic axes.
  // Reduced and clamped as a double before the conversion, so a far outlier (a particle flung
  // to 1e300 m before the run's checks catch it) or a NaN never overflows the int (UB).
  auto index = [](double v, int n, bool wraps) {
    if (wraps) v -= n * std::floor(v / n);  // into [0, n], up to rounding
    if (!(v >= 0)) return 0;
    if (v >= n) return n - 1;
    return static_cast<int>(v);
  };
  const int ix = index((x.x - origin.x) * inv_cell.x, nx, wrap[0]);
  const int iy = index((x.y - origin.y) * inv_cell.y, ny, wrap[1]);
  const int iz = index((x.z - origin.z) * inv_cell.z, nz, wrap[2]);
  return (iz * ny + iy) * nx + ix;
}

// Visits every j in the cells around i with |x_i − x_j| < r_i + r_j + skin (minimum image),
// j > i if kUpperOnly, else every j ≠ i; spheres of i's body are skipped.
template <bool kUpperOnly, class Visit>
void NeighbourList::ForEachCandidate(const Grid& grid, size_t i, const std::vector<Vec3>& x,
                                     const std::vector<double>& r, const std::vector<int>* body,
                                     double skin, Visit&& visit) const {
  const int own_body = body ? (*body)[i] : -1;
  const PeriodicBox& box = periodic_;
  const int c = cell_of_particle_[i];
  const int home[3] = {c % grid.nx, (c / grid.nx) % grid.ny, c / (grid.nx * grid.ny)};
  const int dims[3] = {grid.nx, grid.ny, grid.nz};
  // Neighbour cells per axis, wrapped once here (not per cell: integer division is slow) on
  // periodic axes; a periodic axis with fewer than three cells is searched whole, once.
  int cells[3][3], count[3];
  for (int a = 0; a < 3; ++a) {
    count[a] = 0;
    if (box.IsPeriodic(a) && !grid.wrap[a]) {
      for (int k = 0; k < dims[a]; ++k) cells[a][count[a]++] = k;
      continue;
    }
    for (int k = home[a] - 1; k <= home[a] + 1; ++k) {
      if (grid.wrap[a])
        cells[a][count[a]++] = (k + dims[a]) % dims[a];
      else if (k >= 0 && k < dims[a])
        cells[a][count[a]++] = k;
    }
  }
  // Cells adjacent along x hold adjacent runs of cell_particles_ (BucketIndex lists cell by
  // cell), so where the x cells are consecutive a row of them is one run: one pair of bounds
  // read per row instead of per cell. In a loose pack (a pour's column: less than one particle
  // per cell) those bounds are most of the search's memory reads.
  bool x_consecutive = count[0] > 0;
  for (int k = 1; k < count[0]; ++k)
    x_consecutive = x_consecutive && cells[0][k] == cells[0][k - 1] + 1;
  auto visit_run = [&](uint32_t first, uint32_t last) {
    for (uint32_t s = first; s < last; ++s) {
      const uint32_t j = cell_particles_[s];
      if ((kUpperOnly ? j <= i : j == i) || (own_body >= 0 && (*body)[j] == own_body)) continue;
      const double reach = r[i] + r[j] + skin;
      if (Norm2(box.MinimumImage(x[i] - x[j])) < reach * reach) visit(j);
    }
  };
  for (int cz = 0; cz < count[2]; ++cz) {
    for (int cy = 0; cy < count[1]; ++cy) {
      const int row = (cells[2][cz] * grid.ny + cells[1][cy]) * grid.nx;
      if (x_consecutive) {
        const uint32_t first = cell_start_[row + cells[0][0]];
        const uint32_t last = cell_start_[row + cells[0][count[0] - 1] + 1];
        // No skip by the run's last particle: across cells a run need not be in slot order
        // (particles change cells between re-sorts; other plane orders put x slower).
        visit_run(first, last);
        continue;
      }
      for (int cx = 0; cx < count[0]; ++cx) {
        const int cell = row + cells[0][cx];
        const uint32_t first = cell_start_[cell], last = cell_start_[cell + 1];
        // A cell lists its particles in ascending slot order: one whose last precedes i holds
        // only j < i, skipped whole.
        if (kUpperOnly && (first == last || cell_particles_[last - 1] <= i)) continue;
        visit_run(first, last);
      }
    }
  }
}

// Half-stencil search of a full build on a grid with no periodic axis: each pair of moving
// particles is visited from one side only, so a search reads 5 rows of three x-adjacent cells
// instead of 9 (in a loose column, under one particle per cell, a row's bounds and the loop's
// exit cost more than its candidates). Rows are ordered by (z, y): i visits its own row with
// j > i (as the full search does), the four rows after it whole (j < i included: the caller
// files such a pair under row j), and of the four rows before it only fixed partners
// (j ≥ first_fixed_, never searched themselves), and only in rows that hold any (fixed_rows_).
// The same distance test as ForEachCandidate: the same pairs.
template <class Visit>
void NeighbourList::ForEachForwardCandidate(const Grid& grid, size_t i,
                                            const std::vector<Vec3>& x,
                                            const std::vector<double>& r,
                                            const std::vector<int>* body, double skin,
                                            Visit&& visit) const {
  const int own_body = body ? (*body)[i] : -1;
  const int c = cell_of_particle_[i];
  const int hx = c % grid.nx, hy = (c / grid.nx) % grid.ny, hz = c / (grid.nx * grid.ny);
  const int x_lo = std::max(hx - 1, 0), x_hi = std::min(hx + 1, grid.nx - 1);
  auto visit_row = [&](int row, uint32_t min_j) {
    const uint32_t first = cell_start_[row * grid.nx + x_lo];
    const uint32_t last = cell_start_[row * grid.nx + x_hi + 1];
    for (uint32_t s = first; s < last; ++s) {
      const uint32_t j = cell_particles_[s];
      if (j < min_j || (own_body >= 0 && (*body)[j] == own_body)) continue;
      const double reach = r[i] + r[j] + skin;
      if (Norm2(x[i] - x[j]) < reach * reach) visit(j);
    }
  };
  // Rows of at most kGatherRun particles are copied whole into one buffer (kGatherRun indices
  // whatever the row holds: cell_particles_ ends in that many spare entries) and tested in one
  // loop without branches on the candidates: one loop exit per particle instead of one per row,
  // whose trip counts (0, 1, 2, … in a loose column) no predictor follows. Longer rows (a dense
  // bed of small spheres) are visited as they are.
  uint32_t gathered[5 * kGatherRun];
  uint32_t count = 0, own_count = 0;
  auto gather = [&](int row) {
    const uint32_t first = cell_start_[row * grid.nx + x_lo];
    const uint32_t last = cell_start_[row * grid.nx + x_hi + 1];
    if (last - first > kGatherRun) return false;
    std::copy_n(cell_particles_.data() + first, kGatherRun, gathered + count);
    count += last - first;
    return true;
  };
  const uint32_t own_min = static_cast<uint32_t>(i) + 1;
  for (int dz = -1; dz <= 1; ++dz) {
    const int z = hz + dz;
    if (z < 0 || z >= grid.nz) continue;
    for (int dy = -1; dy <= 1; ++dy) {
      const int y = hy + dy;
      if (y < 0 || y >= grid.ny) continue;
      const int row = z * grid.ny + y;
      if (dz == 0 && dy == 0) {
        if (count == 0 && gather(row)) own_count = count;  // the own row comes first
        else visit_row(row, own_min);
      } else if (dz > 0 || (dz == 0 && dy > 0)) {
        if (!gather(row)) visit_row(row, 0);
      } else if (fixed_rows_[row]) {
        visit_row(row, first_fixed_);
      }
    }
  }
  const Vec3 xi = x[i];
  const double ri = r[i];
  for (uint32_t k = 0; k < count; ++k) {
    const uint32_t j = gathered[k];
    const double reach = ri + r[j] + skin;
    const bool near = Norm2(xi - x[j]) < reach * reach;
    if (near & ((k >= own_count) | (j > i)) && !(own_body >= 0 && (*body)[j] == own_body))
      visit(j);
  }
}

}  // namespace demcal::core
