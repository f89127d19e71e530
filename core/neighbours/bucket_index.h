#pragma once
// BucketIndex: a counting sort of the indices 0 .. keys.size() − 1 into buckets by key (a key
// below 0 leaves its index out): start[b] .. start[b + 1] index `items` for bucket b, each
// bucket in ascending index order. The neighbour list builds its cell bins this way at
// every rebuild.
//
// Serial in an arena of one thread (two passes, no atomics). With more, the counts are atomic
// increments, the items are placed in any order and each bucket is then sorted: the output is
// the serial one exactly (indices are unique), so results do not depend on the thread count.
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <type_traits>
#include <vector>

#include "core/math/parallel_passes.h"

namespace demcal::core {

template <class Key>
void BucketIndex(const std::vector<Key>& keys, size_t buckets, std::vector<uint32_t>& start,
                 std::vector<uint32_t>& items) {
  const size_t m = keys.size();
  auto kept = [&](size_t k) {
    if constexpr (std::is_signed_v<Key>) return keys[k] >= 0;
    else return true;
  };
  start.assign(buckets + 1, 0);
  if (tbb::this_task_arena::max_concurrency() <= 1) {
    for (size_t k = 0; k < m; ++k) start[keys[k] + 1] += kept(k);
    InclusivePrefixSum(start);
    items.resize(start[buckets]);
    std::vector<uint32_t> fill(start.begin(), start.end() - 1);
    for (size_t k = 0; k < m; ++k)
      if (kept(k)) items[fill[keys[k]]++] = static_cast<uint32_t>(k);
    return;
  }
  tbb::parallel_for(tbb::blocked_range<size_t>(0, m), [&](const auto& range) {
    for (size_t k = range.begin(); k != range.end(); ++k)
      if (kept(k))
        std::atomic_ref<uint32_t>(start[keys[k] + 1]).fetch_add(1, std::memory_order_relaxed);
  });
  InclusivePrefixSum(start);
  items.resize(start[buckets]);
  std::vector<uint32_t> fill;
  CopyOf(start, fill);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, m), [&](const auto& range) {
    for (size_t k = range.begin(); k != range.end(); ++k)
      if (kept(k))
        items[std::atomic_ref<uint32_t>(fill[keys[k]]).fetch_add(1, std::memory_order_relaxed)] =
            static_cast<uint32_t>(k);
  });
  tbb::parallel_for(tbb::blocked_range<size_t>(0, buckets), [&](const auto& range) {
    for (size_t b = range.begin(); b != range.end(); ++b)
      std::sort(items.begin() + start[b], items.begin() + start[b + 1]);
  });
}

}  // namespace demcal::core
