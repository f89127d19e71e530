#include "core/walls/triangle_grid.h"

#include <limits>

#include "core/math/bounded_cells.h"

namespace demcal::core {

void TriangleGrid::Build(const std::vector<Vec3>& lo, const std::vector<Vec3>& hi, double cell_m) {
  const size_t n = lo.size();
  item_lo_cell_.assign(n, {0, 0, 0});
  cell_start_.assign(2, 0);
  items_.clear();
  dims_ = {1, 1, 1};
  if (n == 0) return;

  Vec3 box_lo = lo[0], box_hi = hi[0];
  double mean_extent = 0;
  for (size_t i = 0; i < n; ++i) {
    for (int a = 0; a < 3; ++a) {
      box_lo[a] = std::min(box_lo[a], lo[i][a]);
      box_hi[a] = std::max(box_hi[a], hi[i][a]);
    }
    mean_extent += std::max({hi[i].x - lo[i].x, hi[i].y - lo[i].y, hi[i].z - lo[i].z});
  }
  mean_extent /= static_cast<double>(n);
  const Vec3 size = box_hi - box_lo;
  const double diagonal = Norm(size);
  double cell = cell_m > 0 ? cell_m : mean_extent;
  cell = std::max(cell, 1e-9 * diagonal);
  if (!(cell > 0)) cell = 1;  // every box is one point: any cell size will do

  // Enlarge the cells until the grid has a bounded number of them.
  const double max_cells = std::max(64.0, 16.0 * static_cast<double>(n));
  cell = CellForAtMost(size, cell, max_cells, CellRounding::kUp);

  cell_m_ = cell;
  inv_cell_ = 1.0 / cell;
  origin_ = box_lo;
  for (int a = 0; a < 3; ++a) dims_[a] = static_cast<int>(CellsAlong(size[a], cell, CellRounding::kUp));
  // The boxes' own upper corner, not the last cell's: a query above a flat mesh (one cell thick,
  // a cell being a triangle long) then visits nothing instead of every triangle of the layer.
  extent_hi_ = box_hi;

  // Two passes: count the entries per cell, then fill the compressed rows.
  const size_t cells = static_cast<size_t>(dims_[0]) * dims_[1] * dims_[2];
  std::vector<uint32_t> count(cells + 1, 0);
  auto for_each_cell = [&](size_t i, auto&& f) {
    const int x0 = Clamp(0, lo[i].x), x1 = Clamp(0, hi[i].x);
    const int y0 = Clamp(1, lo[i].y), y1 = Clamp(1, hi[i].y);
    const int z0 = Clamp(2, lo[i].z), z1 = Clamp(2, hi[i].z);
    item_lo_cell_[i] = {x0, y0, z0};
    for (int z = z0; z <= z1; ++z) {
      for (int y = y0; y <= y1; ++y) {
        for (int x = x0; x <= x1; ++x) f(CellIndex(x, y, z));
      }
    }
  };
  for (size_t i = 0; i < n; ++i) for_each_cell(i, [&](size_t c) { ++count[c + 1]; });
  for (size_t c = 0; c < cells; ++c) count[c + 1] += count[c];
  cell_start_ = count;
  items_.resize(count[cells]);
  for (size_t i = 0; i < n; ++i) {
    for_each_cell(i, [&](size_t c) { items_[count[c]++] = static_cast<uint32_t>(i); });
  }
}

}  // namespace demcal::core
