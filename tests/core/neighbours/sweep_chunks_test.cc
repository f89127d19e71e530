// SweepChunks: the chunks tile the particle slots, every cross pair (partner in a later chunk)
// is listed exactly once, in its partner's chunk, with a slot that ranks it in entry order, and
// Ensure() starts each chunk exactly once even when many threads ask at the same time.
#include "core/neighbours/sweep_chunks.h"

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <atomic>
#include <catch2/catch.hpp>
#include <random>
#include <vector>

using namespace demcal::core;

namespace {

// A cell-ordered random cloud (as the engine sorts particles) and its neighbour list.
NeighbourList RandomCloudList(size_t n, uint64_t seed, size_t first_fixed = SIZE_MAX) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 0.03);
  std::vector<Vec3> x(n);
  for (Vec3& p : x) p = {u(rng), u(rng), u(rng)};
  const std::vector<double> r(n, 0.001);
  const NeighbourList::Settings s{{0, 0, 0}, {0.03, 0.03, 0.03}, 0.0005, 0.001, {}};
  NeighbourList list;
  const std::vector<uint32_t> order = list.CellOrder(s, x);
  std::vector<Vec3> sorted(n);
  for (size_t k = 0; k < n; ++k) sorted[k] = x[order[k]];
  list.Build(s, sorted, r, nullptr, first_fixed);
  return list;
}

size_t ChunkOf(const SweepChunks& chunks, uint32_t slot) {
  for (size_t c = 0; c < chunks.Count(); ++c)
    if (slot < chunks.End(c)) return c;
  return chunks.Count();
}

// Checks that each cross pair is listed once, in its partner's chunk, and nothing else is, and
// that the slots rank the cross pairs in entry order (so each row chunk's pairs hold the run
// [OutgoingBegin(c), OutgoingBegin(c + 1))); returns the number of cross pairs.
size_t CheckCrossPairs(const NeighbourList& list, const SweepChunks& chunks) {
  std::vector<int> listed(list.PairCount(), 0);
  std::vector<int64_t> slot_of(list.PairCount(), -1);
  for (size_t c = 0; c < chunks.Count(); ++c) {
    for (const SweepChunks::CrossPair& x : chunks.Incoming(c)) {
      CHECK(x.entry >= list.RowBegin(x.row));
      CHECK(x.entry < list.RowEnd(x.row));
      CHECK(ChunkOf(chunks, list.Partner(x.entry)) == c);
      ++listed[x.entry];
      slot_of[x.entry] = x.slot;
    }
  }
  int64_t next_slot = 0;
  size_t misplaced = 0;
  for (uint32_t k = 0; k < list.PairCount(); ++k) {
    if (slot_of[k] < 0) continue;
    misplaced += slot_of[k] != next_slot++;
  }
  CHECK(misplaced == 0);
  CHECK(chunks.OutgoingBegin(0) == 0);
  CHECK(chunks.OutgoingBegin(chunks.Count()) == chunks.CrossPairCount());
  for (uint32_t i = 0; i < list.RowsCount(); ++i)
    for (uint32_t k = list.RowBegin(i); k < list.RowEnd(i); ++k) {
      if (slot_of[k] < 0) continue;
      const size_t c = ChunkOf(chunks, i);
      misplaced += slot_of[k] < chunks.OutgoingBegin(c) || slot_of[k] >= chunks.OutgoingBegin(c + 1);
    }
  CHECK(misplaced == 0);
  size_t cross = 0, wrong = 0;
  for (uint32_t i = 0; i < list.RowsCount(); ++i)
    for (uint32_t k = list.RowBegin(i); k < list.RowEnd(i); ++k) {
      // A fixed partner (beyond the last chunk) belongs to its row's chunk: never a cross pair.
      const bool is_cross = list.Partner(k) < list.FirstFixed() &&
                            ChunkOf(chunks, list.Partner(k)) > ChunkOf(chunks, i);
      cross += is_cross;
      wrong += listed[k] != (is_cross ? 1 : 0);
    }
  CHECK(wrong == 0);
  return cross;
}

}  // namespace

TEST_CASE("chunks tile the slots and list every cross pair once, in the partner's chunk",
          "[unit]") {
  const NeighbourList list = RandomCloudList(3000, 5);
  REQUIRE(list.PairCount() > 3000);
  for (const size_t count : {1, 2, 3, 7}) {
    SweepChunks chunks;
    chunks.Plan(list, count);
    REQUIRE(chunks.Count() == count);
    CHECK(chunks.Begin(0) == 0);
    CHECK(chunks.End(count - 1) == list.RowsCount());
    for (size_t c = 0; c < count; ++c)
      CHECK(chunks.Begin(c) < chunks.End(c));  // no empty chunk on a cloud this size
    const size_t cross = CheckCrossPairs(list, chunks);
    if (count > 1) CHECK(cross > 0);
    // Balanced work (rows + pairs) per chunk, within a few rows' worth.
    const double per_chunk = static_cast<double>(list.PairCount() + list.RowsCount()) / count;
    for (size_t c = 0; c < count; ++c) {
      const double work = list.RowBegin(chunks.End(c)) - list.RowBegin(chunks.Begin(c)) +
                          chunks.End(c) - chunks.Begin(c);
      CHECK(work == Approx(per_chunk).epsilon(0.02));
    }
  }
}

TEST_CASE("Ensure starts each chunk exactly once under contention", "[unit]") {
  const NeighbourList list = RandomCloudList(3000, 9);
  SweepChunks chunks;
  chunks.Plan(list, 6);
  std::vector<std::atomic<int>> evaluated(list.PairCount());
  std::atomic<int> returned_early{0};  // Catch2 assertions are not thread-safe: count here
  tbb::task_arena arena(4);
  for (int pass = 0; pass < 3; ++pass) {
    chunks.ResetClaims();
    // Every task asks for every chunk's set, in different orders.
    arena.execute([&] {
      tbb::parallel_for(0, 24, [&](int t) {
        for (size_t k = 0; k < chunks.Count(); ++k) {
          const size_t c = (k + t) % chunks.Count();
          chunks.Ensure(c, [&](size_t d) {
            for (const SweepChunks::CrossPair& x : chunks.Incoming(d)) ++evaluated[x.entry];
          });
          for (const SweepChunks::CrossPair& x : chunks.Incoming(c))
            if (evaluated[x.entry].load() != pass + 1) ++returned_early;
        }
      });
    });
  }
  CHECK(returned_early == 0);  // every set was complete when Ensure returned
  size_t cross_evaluated_thrice = 0, other_untouched = 0;
  for (uint32_t k = 0; k < list.PairCount(); ++k) {
    cross_evaluated_thrice += evaluated[k] == 3;
    other_untouched += evaluated[k] == 0;
  }
  size_t cross = 0;
  for (size_t c = 0; c < chunks.Count(); ++c) cross += chunks.Incoming(c).size();
  CHECK(cross > 0);
  CHECK(cross_evaluated_thrice == cross);
  CHECK(other_untouched == list.PairCount() - cross);
}

TEST_CASE("Rebalance moves work away from a chunk measured slow, and only then", "[unit]") {
  const NeighbourList list = RandomCloudList(3000, 13);
  SweepChunks chunks;
  chunks.Plan(list, 2);
  const uint32_t planned = chunks.End(0);
  auto time_passes = [&](int passes, double t0, double t1) {
    for (int k = 0; k < passes; ++k) chunks.ResetClaims(), chunks.AddTime(0, t0), chunks.AddTime(1, t1);
  };
  time_passes(9, 3.0, 1.0);
  CHECK_FALSE(chunks.Rebalance(list, false, 10, 0.03));  // too few passes yet
  time_passes(1, 3.0, 1.0);
  REQUIRE(chunks.Rebalance(list, false, 10, 0.03));
  // Chunk 0 took 3/4 of the time: times are equal at 2/3 of its work; moved half-way there.
  CHECK(chunks.End(0) == Approx(planned * 5.0 / 6).epsilon(0.05));
  CheckCrossPairs(list, chunks);
  const uint32_t moved = chunks.End(0);
  time_passes(10, 1.01, 1.0);
  CHECK_FALSE(chunks.Rebalance(list, false, 10, 0.03));  // within tolerance: left alone
  CHECK(chunks.End(0) == moved);
}

TEST_CASE("a rebuilt list keeps the measured split and the timing goes on", "[unit]") {
  const NeighbourList list = RandomCloudList(3000, 13);
  const NeighbourList rebuilt = RandomCloudList(3300, 14);  // more particles, other pairs
  SweepChunks chunks;
  // Chunk 0's share of the work (rows + listed pairs).
  auto first_share = [&](const NeighbourList& l) {
    return static_cast<double>(l.RowBegin(chunks.End(0)) + chunks.End(0)) /
           static_cast<double>(l.PairCount() + l.RowsCount());
  };
  chunks.Plan(list, 2);
  const double planned_share = first_share(list);
  for (int k = 0; k < 10; ++k) chunks.ResetClaims(), chunks.AddTime(0, 3.0), chunks.AddTime(1, 1.0);
  REQUIRE(chunks.Rebalance(list, false, 10, 0.03));  // chunk 0 measured slow: moved
  const double learnt_share = first_share(list);
  CHECK(learnt_share == Approx(planned_share * 5.0 / 6).epsilon(0.01));
  // A rebuild with too short a window: the learnt share carries over to the new list, not the
  // model's even split, and the passes timed before it still count.
  for (int k = 0; k < 6; ++k) chunks.ResetClaims(), chunks.AddTime(0, 1.0), chunks.AddTime(1, 3.0);
  CHECK_FALSE(chunks.Rebalance(rebuilt, true, 10, 0.03));
  CHECK(chunks.End(chunks.Count() - 1) == rebuilt.RowsCount());
  const double carried_share = first_share(rebuilt);
  CHECK(carried_share == Approx(learnt_share).epsilon(0.01));
  CheckCrossPairs(rebuilt, chunks);
  for (int k = 0; k < 4; ++k) chunks.ResetClaims(), chunks.AddTime(0, 1.0), chunks.AddTime(1, 3.0);
  // 6 + 4 passes: a full window across the rebuild. Chunk 1 took 3/4 of the time: the times
  // are equal a third of the way into its work; the boundary moves half-way there.
  REQUIRE(chunks.Rebalance(rebuilt, false, 10, 0.03));
  const double moved_share = first_share(rebuilt);
  CHECK(moved_share == Approx(learnt_share + (1 - learnt_share) / 6).epsilon(0.01));
}

TEST_CASE("chunks cover the moving rows only; pairs with a fixed partner never cross",
          "[unit]") {
  const NeighbourList list = RandomCloudList(3000, 9, 2000);
  size_t fixed_partners = 0;
  for (uint32_t k = 0; k < list.PairCount(); ++k) fixed_partners += list.Partner(k) >= 2000;
  REQUIRE(fixed_partners > 100);
  for (const size_t count : {1, 2, 3}) {
    SweepChunks chunks;
    chunks.Plan(list, count);
    REQUIRE(chunks.Count() == count);
    CHECK(chunks.End(count - 1) == 2000);
    CheckCrossPairs(list, chunks);
  }
}
