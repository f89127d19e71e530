// NeighbourList against a brute-force oracle (docs/design.md, Conventions): the cell
// list must hold exactly the pairs i < j with |x_i − x_j| < r_i + r_j + skin, on random
// polydisperse clouds and on adversarial placements (cell faces, domain faces, outside the
// domain).
#include "core/neighbours/neighbour_list.h"

#include <algorithm>
#include <catch2/catch.hpp>
#include <cstdint>
#include <random>
#include <set>
#include <utility>
#include <vector>

using namespace demcal::core;

namespace {

using PairSet = std::set<std::pair<uint32_t, uint32_t>>;

// The definition of the list, evaluated over all pairs with the same floating-point
// expression as the contract in neighbour_list.h.
// Slots from `first_fixed` on are fixed spheres: pairs among them are not listed.
PairSet BruteForce(const std::vector<Vec3>& x, const std::vector<double>& r, double skin,
                   size_t first_fixed = SIZE_MAX) {
  PairSet pairs;
  for (uint32_t i = 0; i < x.size() && i < first_fixed; ++i) {  // row of a fixed i: all fixed
    for (uint32_t j = i + 1; j < x.size(); ++j) {
      const double reach = r[i] + r[j] + skin;
      if (Norm2(x[i] - x[j]) < reach * reach) pairs.insert({i, j});
    }
  }
  return pairs;
}

PairSet Listed(const NeighbourList& list) {
  PairSet pairs;
  for (uint32_t i = 0; i < list.RowsCount(); ++i)
    for (uint32_t k = list.RowBegin(i); k < list.RowEnd(i); ++k) pairs.insert({i, list.Partner(k)});
  return pairs;
}

// Rows ascending with partners > i and below n, and Find() consistent.
void CheckStructure(const NeighbourList& list, size_t n) {
  REQUIRE(list.RowsCount() == n);
  for (uint32_t i = 0; i < n; ++i) {
    for (uint32_t k = list.RowBegin(i); k < list.RowEnd(i); ++k) {
      REQUIRE(list.Partner(k) > i);
      REQUIRE(list.Partner(k) < n);
      if (k > list.RowBegin(i)) REQUIRE(list.Partner(k - 1) < list.Partner(k));
      REQUIRE(list.Find(i, list.Partner(k)) == static_cast<int64_t>(k));
    }
  }
}

void CheckAgainstBruteForce(const NeighbourList::Settings& settings, const std::vector<Vec3>& x,
                            const std::vector<double>& r, size_t first_fixed = SIZE_MAX) {
  NeighbourList list;
  list.Build(settings, x, r, nullptr, first_fixed);
  CHECK(list.FirstFixed() == std::min(first_fixed, x.size()));
  const PairSet expected = BruteForce(x, r, settings.skin_m, first_fixed);
  const PairSet listed = Listed(list);
  PairSet missing, extra;
  std::set_difference(expected.begin(), expected.end(), listed.begin(), listed.end(),
                      std::inserter(missing, missing.begin()));
  std::set_difference(listed.begin(), listed.end(), expected.begin(), expected.end(),
                      std::inserter(extra, extra.begin()));
  INFO(expected.size() << " pairs expected, " << listed.size() << " listed");
  if (!missing.empty()) {
    const auto [i, j] = *missing.begin();
    INFO("first missing pair " << i << " (" << x[i].x << ", " << x[i].y << ", " << x[i].z << ") – "
                               << j << " (" << x[j].x << ", " << x[j].y << ", " << x[j].z << ")");
    CHECK(missing.empty());
  }
  CHECK(extra.empty());
  CHECK(list.PairCount() == expected.size());  // no duplicates either
  CheckStructure(list, x.size());
}

}  // namespace

TEST_CASE("cell list matches brute force on random polydisperse clouds", "[unit]") {
  const NeighbourList::Settings settings{{-0.1, -0.05, 0.0}, {0.1, 0.07, 0.13}, 0.002, 0.01};
  for (const uint64_t seed : {1u, 2u, 3u, 42u, 1234u}) {
    for (const size_t n : {size_t{0}, size_t{1}, size_t{50}, size_t{2000}}) {
      std::mt19937_64 rng(seed);
      std::uniform_real_distribution<double> radius(0.002, settings.max_radius_m);
      // Positions spill 2 cm beyond the domain on every side: those are clamped into edge cells.
      auto axis = [&](int a) {
        return std::uniform_real_distribution<double>(settings.domain_min_m[a] - 0.02,
                                                      settings.domain_max_m[a] + 0.02)(rng);
      };
      std::vector<Vec3> x(n);
      std::vector<double> r(n);
      for (size_t i = 0; i < n; ++i) {
        x[i] = {axis(0), axis(1), axis(2)};
        r[i] = radius(rng);
      }
      INFO("seed " << seed << ", " << n << " particles");
      CheckAgainstBruteForce(settings, x, r);
    }
  }
}

TEST_CASE("cell list matches brute force at cell faces, domain faces and outside", "[unit]") {
  // Domain extents that are exact multiples of the cut-off 2 r_max + skin = 0.025 (cells of
  // exactly the cut-off) and one that is not (stretched cells); particles of the largest radius
  // at grid planes, a hair either side of them, and partners just inside / outside reach.
  const double r_max = 0.01, skin = 0.005, cutoff = 2 * r_max + skin;
  const NeighbourList::Settings exact{{0, 0, 0}, {4 * cutoff, 3 * cutoff, 2 * cutoff}, skin, r_max};
  const NeighbourList::Settings stretched{
      {-0.0371, 0.013, -0.2}, {0.0893, 0.1, -0.111}, skin, r_max};
  for (const auto& settings : {exact, stretched}) {
    const Vec3 lo = settings.domain_min_m, hi = settings.domain_max_m;
    std::vector<Vec3> x;
    std::vector<double> r;
    auto add = [&](const Vec3& p, double radius) {
      x.push_back(p);
      r.push_back(radius);
    };
    const double eps = 1e-12;
    // Grid planes: the cell size is at least the cut-off; sample planes at multiples of the
    // cut-off (cell faces for `exact`) and at the domain faces.
    std::vector<double> planes_x;
    for (double p = lo.x; p <= hi.x + 1e-15; p += cutoff) planes_x.push_back(p);
    planes_x.push_back(hi.x);
    const double y0 = 0.5 * (lo.y + hi.y), z0 = 0.5 * (lo.z + hi.z);
    for (const double p : planes_x) {
      for (const double d : {-eps, 0.0, eps}) add({p + d, y0, z0}, r_max);
      // Partners along x just within and just beyond reach, on both sides.
      for (const double s : {-1.0, 1.0}) {
        add({p + s * (cutoff * (1 - 1e-9)), y0, z0}, r_max);
        add({p + s * (cutoff * (1 + 1e-9)), y0 + 0.3 * r_max, z0}, r_max);
      }
      // Diagonal partner just within reach.
      const double d = cutoff * (1 - 1e-9) / std::sqrt(3.0);
      add({p + d, y0 + d, z0 + d}, r_max);
    }
    // Domain corners, exactly on them and just outside; far outside (clamped into the corner
    // cell) with a partner next to it.
    for (const double cx : {lo.x, hi.x}) {
      for (const double cy : {lo.y, hi.y}) {
        for (const double cz : {lo.z, hi.z}) {
          add({cx, cy, cz}, r_max);
          const Vec3 out{cx + (cx == lo.x ? -1 : 1) * 0.5 * cutoff,
                         cy + (cy == lo.y ? -1 : 1) * 0.5 * cutoff,
                         cz + (cz == lo.z ? -1 : 1) * 0.5 * cutoff};
          add(out, 0.5 * r_max);
          const Vec3 far{cx + (cx == lo.x ? -1 : 1) * 7 * cutoff, cy, cz};
          add(far, r_max);
          add(far + Vec3{0.9 * cutoff, 0, 0}, r_max);
        }
      }
    }
    // A pair straddling the domain face on y, one inside and one outside.
    add({0.5 * (lo.x + hi.x), hi.y - 0.4 * cutoff, z0}, r_max);
    add({0.5 * (lo.x + hi.x), hi.y + 0.55 * cutoff, z0}, r_max);
    CheckAgainstBruteForce(settings, x, r);
  }
}

TEST_CASE("cell list handles a domain smaller than one cut-off", "[unit]") {
  // Fewer cells than one per axis would give: the grid degenerates to single cells.
  const NeighbourList::Settings tiny{{0, 0, 0}, {0.01, 0.01, 0.01}, 0.001, 0.01};
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-0.05, 0.06);
  std::vector<Vec3> x(300);
  std::vector<double> r(300, 0.004);
  for (Vec3& p : x) p = {u(rng), u(rng), u(rng)};
  CheckAgainstBruteForce(tiny, x, r);
}

TEST_CASE("cell list matches brute force in rows of cells both short and crowded", "[unit]") {
  // A full build gathers a row of three cells into one buffer when it holds at most 16 spheres
  // and visits longer rows one by one: small spheres on a grid sized by the largest one crowd
  // the cells, so both kinds of row and both kinds of partner (moving, fixed) are met here.
  const NeighbourList::Settings settings{{0, 0, 0}, {0.03, 0.03, 0.03}, 0.001, 0.004};
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0.0, 0.03), radius(0.0005, 0.004);
  for (const size_t n : {size_t{60}, size_t{400}, size_t{3000}}) {
    std::vector<Vec3> x(n);
    std::vector<double> r(n);
    for (size_t i = 0; i < n; ++i) x[i] = {u(rng), u(rng), u(rng)}, r[i] = radius(rng);
    for (const size_t first_fixed : {n, n / 2, size_t{1}}) {
      INFO(n << " spheres, first fixed slot " << first_fixed);
      CheckAgainstBruteForce(settings, x, r, first_fixed);
    }
  }
}

TEST_CASE("cell list leaves out fixed-fixed pairs and only those", "[unit]") {
  // Fixed spheres in the slots from first_fixed on: the oracle drops pairs with both there.
  const NeighbourList::Settings settings{{0, 0, 0}, {0.05, 0.05, 0.05}, 0.001, 0.003};
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> u(0.0, 0.05), radius(0.001, 0.003);
  std::vector<Vec3> x(3000);
  std::vector<double> r(3000);
  for (size_t i = 0; i < x.size(); ++i) x[i] = {u(rng), u(rng), u(rng)}, r[i] = radius(rng);
  for (const size_t first_fixed : {size_t{0}, size_t{1}, size_t{1000}, size_t{2999}, size_t{3000}}) {
    INFO("first fixed slot " << first_fixed);
    CheckAgainstBruteForce(settings, x, r, first_fixed);
  }
  // A small moving cluster over a wide fixed bed (a stream on a base): the grid spans only the
  // cluster and a cut-off around it; fixed spheres beyond are not binned, those within are.
  std::uniform_real_distribution<double> cluster(0.02, 0.026), wide(-0.01, 0.06);
  for (size_t i = 0; i < x.size(); ++i)
    x[i] = i < 40 ? Vec3{cluster(rng), cluster(rng), cluster(rng)} : Vec3{wide(rng), wide(rng), wide(rng)};
  const double cutoff = 2 * settings.max_radius_m + settings.skin_m;
  for (int k = 0; k < 40; ++k)  // fixed spheres just inside and outside the cluster's reach
    x[40 + k] = x[k] + Vec3{(k % 2 ? 0.999 : 1.001) * cutoff, 0, 0}, r[40 + k] = 0.003, r[k] = 0.003;
  CheckAgainstBruteForce(settings, x, r, 40);
}

TEST_CASE("a rebuild is due when a moving sphere moves half the skin, never for a fixed one",
          "[unit]") {
  const NeighbourList::Settings settings{{0, 0, 0}, {0.05, 0.05, 0.05}, 0.002, 0.003};
  std::vector<Vec3> x = {{0.01, 0.01, 0.01}, {0.02, 0.01, 0.01}, {0.03, 0.01, 0.01}};
  const std::vector<double> r(3, 0.002);
  NeighbourList list;
  list.Build(settings, x, r, nullptr, 2);  // slot 2 is fixed
  x[2].x += 0.01;  // a fixed sphere is never displaced by the engine: not checked
  CHECK_FALSE(list.NeedsRebuild(x));
  x[1].x += 0.00099;
  CHECK_FALSE(list.NeedsRebuild(x));
  x[1].x += 0.00002;
  CHECK(list.NeedsRebuild(x));
}

TEST_CASE("a far-flung particle in a large domain keeps the cell grid in proportion",
          "[unit][bad_inputs]") {
  // A domain of 200 km per axis (within the coordinate limit) and 2 mm spheres: one particle
  // at the far corner makes the grid span the domain, ≈ 9e7 cut-offs per axis. The grid is
  // capped at NeighbourList::kMaxCellsPerParticle cells per particle (4,096 at least), and the
  // list is still exactly the brute-force one, moving or fixed, built or updated.
  const NeighbourList::Settings huge{{-1e5, -1e5, -1e5}, {1e5, 1e5, 1e5}, 0.0002, 0.001};
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(0.0, 0.02);
  std::vector<Vec3> x(400);
  std::vector<double> r(400, 0.001);
  for (Vec3& p : x) p = {u(rng), u(rng), u(rng)};
  x[123] = {9.9e4, -9.9e4, 9.9e4};
  CheckAgainstBruteForce(huge, x, r);
  CheckAgainstBruteForce(huge, x, r, 300);  // the stray one among the fixed
  NeighbourList list;
  list.Build(huge, x, r);
  const double max_cells = std::max(4096.0, NeighbourList::kMaxCellsPerParticle * x.size());
  CHECK(static_cast<double>(list.Heap().other) <= 4.0 * (max_cells + 1) * 1.5);  // + slack
  NeighbourList moved;
  for (size_t i = 0; i < 40; ++i) x[i] = x[i] + Vec3{0.0003, 0, 0};
  moved.Update(huge, x, r, nullptr, x.size(), list, 0.25);
  REQUIRE(moved.LastMovers() == 40);  // the incremental path, on a grid over the movers
  CHECK(Listed(moved) == BruteForce(moved.ReferencePositions(), r, huge.skin_m));
}
