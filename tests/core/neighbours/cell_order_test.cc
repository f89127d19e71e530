// NeighbourList::CellOrder, the particle order of the engine's periodic re-sort: rows of whole
// planes of cells, z slowest, unless the x-y plane holds more than 2,048 cells; then the planes
// lie across the axis with the most cells, so that a sphere's partners in the next plane stay
// within a core's cache during the force sweep (docs/performance.md, "Large beds").
#include <catch2/catch.hpp>
#include <vector>

#include "core/neighbours/neighbour_list.h"

using namespace demcal::core;

namespace {

constexpr double kRadius = 0.001, kSkin = 0.0005;
constexpr double kCell = 2 * kRadius + kSkin;  // the grid's cut-off: one sphere per cell below

// One sphere at the centre of each cell of an nx x ny x nz block, listed with every coordinate
// descending, so that no order checked below holds unless CellOrder made it; and one at each
// corner of the block, first and last in the list, so that the grid (which spans the spheres)
// has exactly these cells and every centre lies mid-cell, far from a rounding at a cell face.
std::vector<Vec3> Block(int nx, int ny, int nz) {
  const double e = 0.01 * kCell;  // the span a little over n cells: exactly n fit
  std::vector<Vec3> x = {{-e, -e, -e}};
  for (int i = nx - 1; i >= 0; --i)
    for (int k = nz - 1; k >= 0; --k)
      for (int j = ny - 1; j >= 0; --j)
        x.push_back({(i + 0.5) * kCell, (j + 0.5) * kCell, (k + 0.5) * kCell});
  x.push_back({nx * kCell + e, ny * kCell + e, nz * kCell + e});
  return x;
}

// Position component `axis` of the spheres in CellOrder's order.
std::vector<double> Along(const std::vector<Vec3>& x, int nx, int ny, int nz, int axis) {
  const NeighbourList::Settings s{
      {-kCell, -kCell, -kCell}, {(nx + 1) * kCell, (ny + 1) * kCell, (nz + 1) * kCell}, kSkin,
      kRadius};
  const std::vector<uint32_t> order = NeighbourList().CellOrder(s, x);
  REQUIRE(order.size() == x.size());
  std::vector<double> along;
  for (uint32_t slot : order) along.push_back(x[slot][axis]);
  return along;
}

bool NonDecreasing(const std::vector<double>& v) {
  for (size_t i = 1; i < v.size(); ++i)
    if (v[i] < v[i - 1]) return false;
  return true;
}

}  // namespace

TEST_CASE("a small grid is re-sorted in planes across z, x fastest", "[unit]") {
  const std::vector<Vec3> x = Block(20, 20, 4);  // a 400-cell plane
  CHECK(NonDecreasing(Along(x, 20, 20, 4, 2)));
  CHECK_FALSE(NonDecreasing(Along(x, 20, 20, 4, 0)));
}

TEST_CASE("a wide flat grid is re-sorted in planes across its longest axis", "[unit]") {
  // 60 x 50 cells = 3,000 per x-y plane: the planes lie across x (60 cells), 50 x 4 cells each.
  const std::vector<Vec3> wide_in_x = Block(60, 50, 4);
  CHECK(NonDecreasing(Along(wide_in_x, 60, 50, 4, 0)));
  CHECK_FALSE(NonDecreasing(Along(wide_in_x, 60, 50, 4, 2)));
  // The same block turned: y is now the longest axis.
  std::vector<Vec3> wide_in_y;
  for (const Vec3& p : wide_in_x) wide_in_y.push_back({p.y, p.x, p.z});
  CHECK(NonDecreasing(Along(wide_in_y, 50, 60, 4, 1)));
  CHECK_FALSE(NonDecreasing(Along(wide_in_y, 50, 60, 4, 0)));
}
