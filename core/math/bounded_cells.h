#pragma once
// Cell grids with a bounded number of cells: the cell size grows from its natural value by
// factors of 1.25 until a grid over the span has at most `max_cells` cells. Used where a grid's
// span can be far larger than what it holds (a stray particle, a huge region, a sparse mesh):
// larger cells only make a query look at more items, never miss one.
#include <algorithm>
#include <cmath>

#include "core/math/vec3.h"

namespace demcal::core {

enum class CellRounding { kDown, kUp };  // cells per axis: stretched to the span, or covering it

// Cells along a span of `extent` at cell size `cell`, at least 1; in double (capped at 1e9), as
// the span over a cell may exceed any int.
inline double CellsAlong(double extent, double cell, CellRounding rounding) {
  const double n = rounding == CellRounding::kUp ? std::ceil(extent / cell)
                                                 : std::floor(extent / cell);
  return std::max(1.0, std::min(n, 1e9));
}

// The smallest cell size cell · 1.25^k (k ≥ 0) whose grid over `extent` has at most `max_cells`.
inline double CellForAtMost(const Vec3& extent, double cell, double max_cells,
                            CellRounding rounding) {
  auto total = [&](double c) {
    return CellsAlong(extent[0], c, rounding) * CellsAlong(extent[1], c, rounding) *
           CellsAlong(extent[2], c, rounding);
  };
  while (total(cell) > max_cells) cell *= 1.25;
  return cell;
}

}  // namespace demcal::core
