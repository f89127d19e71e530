#include "core/neighbours/sweep_chunks.h"

#include <algorithm>
#include <numeric>

namespace demcal::core {

void SweepChunks::Plan(const NeighbourList& list, size_t count) {
  const size_t rows = list.FirstFixed();
  count = std::clamp<size_t>(count, 1, std::max<size_t>(rows, 1));
  const double per_chunk = WorkBefore(list, rows) / count;
  std::vector<double> targets(count - 1);
  for (size_t c = 1; c < count; ++c) targets[c - 1] = per_chunk * c;
  SplitRows(list, targets);
}

bool SweepChunks::Rebalance(const NeighbourList& list, int min_passes, double tolerance) {
  const size_t count = Count();
  if (passes_ < min_passes || count < 2) return false;
  const double total = std::accumulate(time_s_.begin(), time_s_.end(), 0.0);
  const double slowest = *std::max_element(time_s_.begin(), time_s_.end());
  const bool balanced = slowest <= (1 + tolerance) * total / count;
  if (balanced || *std::min_element(time_s_.begin(), time_s_.end()) <= 0) {
    std::fill(time_s_.begin(), time_s_.end(), 0.0), passes_ = 0;
    return false;
  }
  // Measured time is piecewise linear in work (one slope per chunk): place each boundary where
  // the cumulative time reaches its share.
  std::vector<double> targets(count - 1);
  size_t c = 0;
  double time_before = 0;
  for (size_t b = 1; b < count; ++b) {
    const double share = total * b / count;
    while (c + 1 < count && time_before + time_s_[c] < share) time_before += time_s_[c++];
    const double work = WorkBefore(list, End(c)) - WorkBefore(list, Begin(c));
    const double balanced_at = WorkBefore(list, Begin(c)) + (share - time_before) / time_s_[c] * work;
    // Half-way only: part of a window's imbalance is noise (other processes, cache misses).
    targets[b - 1] = 0.5 * (WorkBefore(list, Begin(b)) + balanced_at);
  }
  SplitRows(list, targets);
  return true;
}

void SweepChunks::SplitRows(const NeighbourList& list, const std::vector<double>& targets) {
  const size_t n = list.FirstFixed();
  boundary_.assign(targets.size() + 2, static_cast<uint32_t>(n));
  boundary_[0] = 0;
  // WorkBefore grows with the row: binary-search each boundary.
  for (size_t c = 1; c <= targets.size(); ++c) {
    size_t lo = boundary_[c - 1], hi = n;
    while (lo < hi) {
      const size_t mid = (lo + hi) / 2;
      if (WorkBefore(list, mid) >= targets[c - 1]) hi = mid;
      else lo = mid + 1;
    }
    boundary_[c] = static_cast<uint32_t>(lo);
  }
  CollectCrossPairs(list);
  claim_ = std::make_unique<std::atomic<uint8_t>[]>(Count());
  time_s_.assign(Count(), 0.0);
  passes_ = 0;
}

void SweepChunks::CollectCrossPairs(const NeighbourList& list) {
  const size_t count = Count();
  incoming_start_.assign(count + 1, 0);
  outgoing_start_.assign(count + 1, 0);
  incoming_.clear();
  // Rows are swept in order, so each chunk's set comes out in ascending entry order; counted
  // first so the sets can be laid out contiguously.
  const uint32_t first_fixed = list.FirstFixed();
  auto for_each_cross = [&](auto&& visit) {
    for (size_t c = 0; c + 1 < count; ++c) {
      for (uint32_t i = Begin(c); i < End(c); ++i) {
        const uint32_t row_end = list.RowEnd(i);
        if (row_end == list.RowBegin(i) || list.Partner(row_end - 1) < End(c)) continue;
        size_t d = c;
        for (uint32_t k = list.RowBegin(i); k < row_end; ++k) {
          const uint32_t j = list.Partner(k);
          if (j < End(c)) continue;
          if (j >= first_fixed) break;  // fixed partners (ascending, last): not cross pairs
          while (j >= End(d)) ++d;  // partners ascend, so d only moves forward
          visit(c, d, CrossPair{i, k, 0});
        }
      }
    }
  };
  for_each_cross([&](size_t c, size_t d, const CrossPair&) {
    ++outgoing_start_[c + 1];
    ++incoming_start_[d + 1];
  });
  for (size_t c = 0; c < count; ++c) {
    incoming_start_[c + 1] += incoming_start_[c];
    outgoing_start_[c + 1] += outgoing_start_[c];
  }
  incoming_.resize(incoming_start_[count]);
  std::vector<uint32_t> fill(incoming_start_.begin(), incoming_start_.end() - 1);
  uint32_t slot = 0;  // pairs are visited in entry order: the slot is the visit's rank
  for_each_cross([&](size_t, size_t d, CrossPair x) {
    x.slot = slot++;
    incoming_[fill[d]++] = x;
  });
}

void SweepChunks::ResetClaims() {
  for (size_t c = 0; c < Count(); ++c) claim_[c].store(kPending, std::memory_order_relaxed);
  ++passes_;
}

}  // namespace demcal::core
