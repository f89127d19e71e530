// NeighbourList::Update (the incremental rebuild) against a brute-force oracle over the
// reference positions: after any chain of updates the list holds exactly the pairs i < j
// (not both fixed) with |p_i − p_j| < r_i + r_j + skin, where p_i is the particle's position at
// its last re-search; only particles beyond the refresh distance get a new reference; the list
// is the same for any thread count.
#include <tbb/task_arena.h>

#include <catch2/catch.hpp>
#include <cstdint>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include "core/neighbours/neighbour_list.h"

using namespace demcal::core;

namespace {

using PairSet = std::set<std::pair<uint32_t, uint32_t>>;

PairSet BruteForceOverReferences(const NeighbourList& list, const std::vector<double>& r,
                                 double skin) {
  PairSet pairs;
  const size_t n = list.RowsCount();
  for (uint32_t i = 0; i < n && i < list.FirstFixed(); ++i)
    for (uint32_t j = i + 1; j < n; ++j) {
      const double reach = r[i] + r[j] + skin;
      if (Norm2(list.ReferencePosition(i) - list.ReferencePosition(j)) < reach * reach)
        pairs.insert({i, j});
    }
  return pairs;
}

PairSet Listed(const NeighbourList& list) {
  PairSet pairs;
  for (uint32_t i = 0; i < list.RowsCount(); ++i)
    for (uint32_t k = list.RowBegin(i); k < list.RowEnd(i); ++k) {
      REQUIRE(list.Partner(k) > i);
      if (k > list.RowBegin(i)) REQUIRE(list.Partner(k - 1) < list.Partner(k));
      pairs.insert({i, list.Partner(k)});
    }
  return pairs;
}

std::vector<uint32_t> Flat(const NeighbourList& list) {
  std::vector<uint32_t> out;
  for (uint32_t i = 0; i <= list.RowsCount(); ++i)
    out.push_back(i < list.RowsCount() ? list.RowBegin(i) : list.RowEnd(i - 1));
  for (uint32_t k = 0; k < list.PairCount(); ++k) out.push_back(list.Partner(k));
  return out;
}

struct Cloud {
  std::vector<Vec3> x;
  std::vector<double> r;
};

// A dense random cloud in a 4 cm box; slots from `first_fixed` on are fixed.
Cloud MakeCloud(size_t n, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 0.04), radius(0.001, 0.0015);
  Cloud c;
  for (size_t i = 0; i < n; ++i)
    c.x.push_back({u(rng), u(rng), u(rng)}), c.r.push_back(radius(rng));
  return c;
}

// Moves a fraction of the moving particles by up to `step` (m) per axis.
void Jiggle(Cloud& c, size_t first_fixed, double fraction, double step, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0, 1), d(-step, step);
  for (size_t i = 0; i < first_fixed; ++i)
    if (u(rng) < fraction) c.x[i] += Vec3{d(rng), d(rng), d(rng)};
}

}  // namespace

TEST_CASE("incremental rebuild matches brute force over reference positions", "[unit]") {
  const double skin = 0.0008;
  const NeighbourList::Settings settings{{0, 0, 0}, {0.04, 0.04, 0.04}, skin, 0.0015};
  for (const size_t first_fixed : {size_t{1500}, size_t{900}, size_t{0}}) {
    Cloud c = MakeCloud(1500, 5 + first_fixed);
    std::mt19937_64 rng(first_fixed);
    NeighbourList a, b;
    a.Build(settings, c.x, c.r, nullptr, first_fixed);
    NeighbourList* current = &a;
    NeighbourList* spare = &b;
    size_t incremental = 0;
    for (int round = 0; round < 12; ++round) {
      // A few rounds move most particles (a full build), most move some.
      Jiggle(c, first_fixed, round % 5 == 4 ? 0.9 : 0.1, 0.4 * skin, rng);
      const std::vector<Vec3> before = [&] {
        std::vector<Vec3> p;
        for (size_t i = 0; i < c.x.size(); ++i) p.push_back(current->ReferencePosition(i));
        return p;
      }();
      std::swap(current, spare);
      current->Update(settings, c.x, c.r, nullptr, first_fixed, *spare, 0.25);
      incremental += current->LastMovers() < first_fixed;
      INFO("first fixed " << first_fixed << ", round " << round);
      const PairSet expected = BruteForceOverReferences(*current, c.r, skin);
      const PairSet listed = Listed(*current);
      CHECK(listed == expected);
      CHECK(current->PairCount() == expected.size());
      // References: moved ones (beyond a quarter skin) are where they are now, others unchanged.
      size_t kept = 0;
      for (size_t i = 0; i < c.x.size(); ++i) {
        const bool moved = Norm2(c.x[i] - before[i]) > 0.0625 * skin * skin;
        const Vec3 want = moved || current->LastMovers() == first_fixed ? c.x[i] : before[i];
        if (i < first_fixed) CHECK(current->ReferencePosition(i) == want);
        kept += current->ReferencePosition(i) == before[i] && !(c.x[i] == before[i]);
      }
      if (first_fixed > 0 && current->LastMovers() < first_fixed) CHECK(kept > 0);
      CHECK_FALSE(current->NeedsRebuild(c.x));  // every particle within half the skin
    }
    if (first_fixed > 0) CHECK(incremental >= 6);  // the incremental path was taken
  }
}

TEST_CASE("incremental rebuild is the same for any thread count", "[unit]") {
  const double skin = 0.0008;
  const NeighbourList::Settings settings{{0, 0, 0}, {0.04, 0.04, 0.04}, skin, 0.0015};
  std::vector<std::vector<uint32_t>> results;
  for (const int threads : {1, 2, 4}) {
    Cloud c = MakeCloud(4000, 99);
    std::mt19937_64 rng(3);
    NeighbourList a, b;
    tbb::task_arena arena(threads);
    arena.execute([&] {
      a.Build(settings, c.x, c.r, nullptr, 3000);
      for (int round = 0; round < 4; ++round) {
        Jiggle(c, 3000, 0.2, 0.4 * skin, rng);
        (round % 2 ? a : b).Update(settings, c.x, c.r, nullptr, 3000, round % 2 ? b : a, 0.25);
      }
    });
    results.push_back(Flat(a));
    CHECK(a.LastMovers() < 3000);
  }
  CHECK(results[0] == results[1]);
  CHECK(results[0] == results[2]);
}

TEST_CASE("incremental rebuild falls back to a full build when the slots change", "[unit]") {
  const NeighbourList::Settings settings{{0, 0, 0}, {0.04, 0.04, 0.04}, 0.0008, 0.0015};
  Cloud c = MakeCloud(500, 1);
  NeighbourList a, b;
  a.Build(settings, c.x, c.r, nullptr, 400);
  c.x.push_back({0.02, 0.02, 0.02}), c.r.push_back(0.001);  // a newcomer
  b.Update(settings, c.x, c.r, nullptr, 400, a, 0.25);
  CHECK(b.LastMovers() == 400);  // every moving particle searched
  CHECK(Listed(b) == BruteForceOverReferences(b, c.r, settings.skin_m));
}

TEST_CASE("a removal compacts the previous list and the rebuild stays incremental", "[unit]") {
  const double skin = 0.0008;
  const NeighbourList::Settings settings{{0, 0, 0}, {0.04, 0.04, 0.04}, skin, 0.0015};
  const size_t n = 1500, first_fixed = 1200;
  Cloud c = MakeCloud(n, 17);
  std::mt19937_64 rng(4);
  NeighbourList a, compacted, b;
  a.Build(settings, c.x, c.r, nullptr, first_fixed);
  Jiggle(c, first_fixed, 0.1, 0.4 * skin, rng);
  // A sink takes every 7th moving slot: the survivors keep their order (ParticleSystem::Remove).
  std::vector<uint32_t> order;
  Cloud kept;
  for (uint32_t s = 0; s < n; ++s) {
    if (s < first_fixed && s % 7 == 3) continue;
    order.push_back(s);
    kept.x.push_back(c.x[s]), kept.r.push_back(c.r[s]);
  }
  const size_t moving = first_fixed - (first_fixed + 3) / 7;
  REQUIRE(compacted.CompactFrom(a, order, moving));
  b.Update(settings, kept.x, kept.r, nullptr, moving, compacted, 0.25);
  CHECK(b.LastMovers() < moving);  // incremental: not every moving particle searched
  CHECK(Listed(b) == BruteForceOverReferences(b, kept.r, skin));
  for (size_t s = 0; s < order.size(); ++s) {  // unmoved survivors keep their references
    const Vec3& before = a.ReferencePosition(order[s]);
    if (Norm2(kept.x[s] - before) <= 0.0625 * skin * skin)
      CHECK(b.ReferencePosition(s) == before);
  }
  CHECK_FALSE(b.NeedsRebuild(kept.x));

  // Not a compaction: a permutation, a newcomer, a fixed sphere counted as moving.
  std::vector<uint32_t> swapped = order;
  std::swap(swapped[0], swapped[1]);
  CHECK_FALSE(compacted.CompactFrom(a, swapped, moving));
  std::vector<uint32_t> with_newcomer = order;
  with_newcomer.push_back(static_cast<uint32_t>(n));
  CHECK_FALSE(compacted.CompactFrom(a, with_newcomer, moving));
  CHECK_FALSE(compacted.CompactFrom(a, order, moving + 1));
  CHECK_FALSE(compacted.CompactFrom(a, order, moving - 1));
}
