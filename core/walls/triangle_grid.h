#pragma once
// TriangleGrid: a uniform grid over axis-aligned boxes (one per triangle of a mesh), the broad
// phase of TriangleMesh queries. Each box is listed in every cell it overlaps (compressed rows);
// a query box visits each overlapping item exactly once, without a visited-set: an item is
// reported only from the first cell (lowest x, y, z) that both boxes share.
//
// Units: metres, in the coordinates the boxes were given in. Thread-safety: Build is not
// thread-safe; ForEachInBox is const and safe to call concurrently.
//
// Usage:
//   grid.Build(lo, hi, /*cell_m=*/0);                   // 0 = automatic cell size
//   grid.ForEachInBox(q_lo, q_hi, [&](uint32_t item) { ... });
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "core/math/vec3.h"

namespace demcal::core {

class TriangleGrid {
 public:
  // Bins the boxes [lo[i], hi[i]]. cell_m <= 0 picks the mean largest box extent, enlarged if
  // needed so that the grid has at most max(64, 16 × boxes) cells.
  void Build(const std::vector<Vec3>& lo, const std::vector<Vec3>& hi, double cell_m);

  // Calls visit(item) once for each box that overlaps [lo, hi] in at least one shared cell
  // (a superset of the boxes that truly overlap it; every such box is visited); nothing when
  // [lo, hi] lies outside the bounding box of all boxes.
  template <class Visit>
  void ForEachInBox(const Vec3& lo, const Vec3& hi, Visit&& visit) const;

  double cell_m() const { return cell_m_; }
  std::array<int, 3> dims() const { return dims_; }
  size_t entries() const { return items_.size(); }

 private:
  // Cell coordinate of x along axis a, clamped into the grid.
  int Clamp(int a, double x) const {
    const double c = std::floor((x - origin_[a]) * inv_cell_);
    return static_cast<int>(std::clamp(c, 0.0, static_cast<double>(dims_[a] - 1)));
  }
  size_t CellIndex(int x, int y, int z) const {
    return static_cast<size_t>(x) +
           static_cast<size_t>(dims_[0]) *
               (static_cast<size_t>(y) + static_cast<size_t>(dims_[1]) * z);
  }

  Vec3 origin_, extent_hi_;  // the boxes' bounding box
  double cell_m_ = 1, inv_cell_ = 1;
  std::array<int, 3> dims_{1, 1, 1};
  std::vector<uint32_t> cell_start_{0};
  std::vector<uint32_t> items_;
  std::vector<std::array<int, 3>> item_lo_cell_;  // lowest cell of each item's box
};

template <class Visit>
void TriangleGrid::ForEachInBox(const Vec3& lo, const Vec3& hi, Visit&& visit) const {
  if (item_lo_cell_.empty() || !IsFinite(lo) || !IsFinite(hi)) return;
  for (int a = 0; a < 3; ++a) {
    if (hi[a] < origin_[a] || lo[a] > extent_hi_[a]) return;  // outside every box
  }
  const int x0 = Clamp(0, lo.x), x1 = Clamp(0, hi.x);
  const int y0 = Clamp(1, lo.y), y1 = Clamp(1, hi.y);
  const int z0 = Clamp(2, lo.z), z1 = Clamp(2, hi.z);
  for (int z = z0; z <= z1; ++z) {
    for (int y = y0; y <= y1; ++y) {
      for (int x = x0; x <= x1; ++x) {
        const size_t c = CellIndex(x, y, z);
        for (uint32_t k = cell_start_[c]; k < cell_start_[c + 1]; ++k) {
          const uint32_t item = items_[k];
          const std::array<int, 3>& first = item_lo_cell_[item];
          if (std::max(x0, first[0]) == x && std::max(y0, first[1]) == y &&
              std::max(z0, first[2]) == z) {
            visit(item);
          }
        }
      }
    }
  }
}

}  // namespace demcal::core
