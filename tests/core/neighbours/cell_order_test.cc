// NeighbourList::CellOrder, the particle order of the engine's periodic re-sort: rows of whole
// planes of cells, z slowest, unless a plane across z holds more than 4,500 of the spheres the
// force sweep visits; then the planes lie across the axis with the most cells, so that a sphere's
// partners in the next plane stay within a core's cache during the force sweep
// (docs/performance.md, "Large beds"). Fixed spheres the sweep skips, and the empty cells of a
// wide grid, do not make a plane large.
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
std::vector<double> Along(const std::vector<Vec3>& x, int nx, int ny, int nz, int axis,
                          const std::vector<uint8_t>& swept = {}) {
  const NeighbourList::Settings s{
      {-kCell, -kCell, -kCell}, {(nx + 1) * kCell, (ny + 1) * kCell, (nz + 1) * kCell}, kSkin,
      kRadius};
  const std::vector<uint32_t> order = NeighbourList().CellOrder(s, x, swept);
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
  // 80 x 60 cells = 4,800 spheres per x-y plane: the planes lie across x (80 cells), 60 x 2
  // cells each.
  const std::vector<Vec3> wide_in_x = Block(80, 60, 2);
  CHECK(NonDecreasing(Along(wide_in_x, 80, 60, 2, 0)));
  CHECK_FALSE(NonDecreasing(Along(wide_in_x, 80, 60, 2, 2)));
  // The same block turned: y is now the longest axis.
  std::vector<Vec3> wide_in_y;
  for (const Vec3& p : wide_in_x) wide_in_y.push_back({p.y, p.x, p.z});
  CHECK(NonDecreasing(Along(wide_in_y, 60, 80, 2, 1)));
  CHECK_FALSE(NonDecreasing(Along(wide_in_y, 60, 80, 2, 0)));
}

TEST_CASE("spheres the sweep skips do not make a plane large", "[unit]") {
  // The block above with every other sphere fixed: 2,400 swept spheres per plane.
  const std::vector<Vec3> x = Block(80, 60, 2);
  std::vector<uint8_t> swept(x.size());
  for (size_t i = 0; i < x.size(); ++i) swept[i] = i % 2;
  CHECK(NonDecreasing(Along(x, 80, 60, 2, 2, swept)));
  CHECK_FALSE(NonDecreasing(Along(x, 80, 60, 2, 0, swept)));
}

TEST_CASE("a wide grid of nearly empty planes keeps the planes across z", "[unit]") {
  // A column of 10 x 10 x 40 occupied cells in a grid 80 x 60 cells wide (a pour's column over
  // a wide base): 100 spheres per plane, 4,800 cells.
  const std::vector<Vec3> block = Block(80, 60, 40);
  std::vector<Vec3> x = {block.front()};
  for (const Vec3& p : block)
    if (p.x > 0 && p.y > 0 && p.x < 10 * kCell && p.y < 10 * kCell) x.push_back(p);
  x.push_back(block.back());
  REQUIRE(x.size() == 10 * 10 * 40 + 2);
  CHECK(NonDecreasing(Along(x, 80, 60, 40, 2)));
}
