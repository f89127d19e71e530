#include "core/sweep_chunks.h"

#include <algorithm>

namespace demcal::core {

void SweepChunks::Plan(const NeighbourList& list, size_t count) {
  const size_t rows = list.RowsCount();
  SplitRows(list, std::clamp<size_t>(count, 1, std::max<size_t>(rows, 1)));
  CollectCrossPairs(list);
  claim_ = std::make_unique<std::atomic<uint8_t>[]>(Count());
}

void SweepChunks::SplitRows(const NeighbourList& list, size_t count) {
  const size_t n = list.RowsCount();
  boundary_.assign(count + 1, static_cast<uint32_t>(n));
  boundary_[0] = 0;
  // Work before row i, RowBegin(i) + i, grows with i: binary-search each boundary.
  const double per_chunk = static_cast<double>(list.PairCount() + n) / count;
  for (size_t c = 1; c < count; ++c) {
    size_t lo = boundary_[c - 1], hi = n;
    while (lo < hi) {
      const size_t mid = (lo + hi) / 2;
      if (list.RowBegin(mid) + mid >= per_chunk * c) hi = mid;
      else lo = mid + 1;
    }
    boundary_[c] = static_cast<uint32_t>(lo);
  }
}

void SweepChunks::CollectCrossPairs(const NeighbourList& list) {
  const size_t count = Count();
  incoming_start_.assign(count + 1, 0);
  incoming_.clear();
  // Rows are swept in order, so each chunk's set comes out in ascending entry order; counted
  // first so the sets can be laid out contiguously.
  auto for_each_cross = [&](auto&& visit) {
    for (size_t c = 0; c + 1 < count; ++c) {
      for (uint32_t i = Begin(c); i < End(c); ++i) {
        const uint32_t row_end = list.RowEnd(i);
        if (row_end == list.RowBegin(i) || list.Partner(row_end - 1) < End(c)) continue;
        size_t d = c;
        for (uint32_t k = list.RowBegin(i); k < row_end; ++k) {
          const uint32_t j = list.Partner(k);
          if (j < End(c)) continue;
          while (j >= End(d)) ++d;  // partners ascend, so d only moves forward
          visit(d, CrossPair{i, k});
        }
      }
    }
  };
  for_each_cross([&](size_t d, const CrossPair&) { ++incoming_start_[d + 1]; });
  for (size_t c = 0; c < count; ++c) incoming_start_[c + 1] += incoming_start_[c];
  incoming_.resize(incoming_start_[count]);
  std::vector<uint32_t> fill(incoming_start_.begin(), incoming_start_.end() - 1);
  for_each_cross([&](size_t d, const CrossPair& x) { incoming_[fill[d]++] = x; });
}

void SweepChunks::ResetClaims() {
  for (size_t c = 0; c < Count(); ++c) claim_[c].store(kPending, std::memory_order_relaxed);
}

}  // namespace demcal::core
