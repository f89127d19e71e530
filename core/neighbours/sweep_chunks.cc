#include "core/neighbours/sweep_chunks.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <numeric>

namespace demcal::core {

void SweepChunks::Plan(const NeighbourList& list, size_t count) {
  const size_t rows = list.FirstFixed();
  count = std::clamp<size_t>(count, 1, std::max<size_t>(rows, 1));
  std::vector<double> shares(count + 1);
  for (size_t c = 0; c <= count; ++c) shares[c] = static_cast<double>(c) / count;
  SplitRows(list, shares, true);
}

bool SweepChunks::Rebalance(const NeighbourList& list, bool list_changed, int min_passes,
                            double tolerance) {
  const size_t count = Count();
  const double total = std::accumulate(time_s_.begin(), time_s_.end(), 0.0);
  const double slowest = count > 1 ? *std::max_element(time_s_.begin(), time_s_.end()) : 0;
  const bool window_full = passes_ >= min_passes && count > 1;
  const bool measured = window_full && *std::min_element(time_s_.begin(), time_s_.end()) > 0;
  if (!measured || slowest <= (1 + tolerance) * total / count) {
    if (window_full) std::fill(time_s_.begin(), time_s_.end(), 0.0), passes_ = 0;  // a new one
    if (list_changed) SplitRows(list, share_, false);
    return false;
  }
  // Measured time is piecewise linear in work (one slope per chunk): place each boundary where
  // the cumulative time reaches its share.
  std::vector<double> shares = share_;
  size_t c = 0;
  double time_before = 0;
  for (size_t b = 1; b < count; ++b) {
    const double time_share = total * b / count;
    while (c + 1 < count && time_before + time_s_[c] < time_share) time_before += time_s_[c++];
    const double balanced_at =
        share_[c] + (time_share - time_before) / time_s_[c] * (share_[c + 1] - share_[c]);
    // Half-way only: part of a window's imbalance is noise (other processes, cache misses).
    shares[b] = 0.5 * (share_[b] + balanced_at);
  }
  SplitRows(list, shares, true);
  return true;
}

void SweepChunks::SplitRows(const NeighbourList& list, const std::vector<double>& shares,
                            bool restart_timing) {
  const size_t n = list.FirstFixed();
  const size_t count = shares.size() - 1;
  const double total = WorkBefore(list, n);
  boundary_.assign(count + 1, static_cast<uint32_t>(n));
  boundary_[0] = 0;
  // WorkBefore grows with the row: binary-search each boundary.
  for (size_t c = 1; c < count; ++c) {
    size_t lo = boundary_[c - 1], hi = n;
    while (lo < hi) {
      const size_t mid = (lo + hi) / 2;
      if (WorkBefore(list, mid) >= shares[c] * total) hi = mid;
      else lo = mid + 1;
    }
    boundary_[c] = static_cast<uint32_t>(lo);
  }
  share_ = shares;
  CollectCrossPairs(list);
  if (time_s_.size() != count) {  // a new chunk count: new claims and timing
    claim_ = std::make_unique<std::atomic<uint8_t>[]>(count);
    restart_timing = true;
  }
  if (restart_timing) time_s_.assign(count, 0.0), passes_ = 0;
}

void SweepChunks::CollectCrossPairs(const NeighbourList& list) {
  const size_t count = Count();
  const uint32_t first_fixed = list.FirstFixed();
  // The cross pairs of chunk c's rows, in entry order, with the chunk d of each partner.
  auto for_each_cross = [&](size_t c, auto&& visit) {
    if (c + 1 == count) return;  // the last chunk's partners all lie in it, or are fixed
    for (uint32_t i = Begin(c); i < End(c); ++i) {
      const uint32_t row_end = list.RowEnd(i);
      if (row_end == list.RowBegin(i) || list.Partner(row_end - 1) < End(c)) continue;
      size_t d = c;
      for (uint32_t k = list.RowBegin(i); k < row_end; ++k) {
        const uint32_t j = list.Partner(k);
        if (j < End(c)) continue;
        if (j >= first_fixed) break;  // fixed partners (ascending, last): not cross pairs
        while (j >= End(d)) ++d;  // partners ascend, so d only moves forward
        visit(d, CrossPair{i, k, 0});
      }
    }
  };
  // Counted per (row chunk, partner chunk), the chunks in parallel (a rebuild and every
  // re-plan run this: serial, it rivalled a pour's parallel sweep at 16 threads); then laid
  // out so that each incoming set is in entry order (row chunks ascending, then entries) and
  // the slots rank all cross pairs in entry order.
  counts_.assign(count * count, 0);
  tbb::parallel_for(size_t{0}, count, [&](size_t c) {
    for_each_cross(c, [&](size_t d, const CrossPair&) { ++counts_[c * count + d]; });
  });
  incoming_start_.assign(count + 1, 0);
  outgoing_start_.assign(count + 1, 0);
  for (size_t c = 0; c < count; ++c)
    for (size_t d = 0; d < count; ++d) {
      incoming_start_[d + 1] += counts_[c * count + d];
      outgoing_start_[c + 1] += counts_[c * count + d];
    }
  for (size_t c = 0; c < count; ++c) {
    incoming_start_[c + 1] += incoming_start_[c];
    outgoing_start_[c + 1] += outgoing_start_[c];
  }
  // counts_ becomes each (row chunk, partner chunk) run's first place in incoming_.
  for (size_t d = 0; d < count; ++d) {
    uint32_t place = incoming_start_[d];
    for (size_t c = 0; c < count; ++c) {
      const uint32_t n = counts_[c * count + d];
      counts_[c * count + d] = place;
      place += n;
    }
  }
  incoming_.resize(incoming_start_[count]);
  tbb::parallel_for(size_t{0}, count, [&](size_t c) {
    uint32_t* const place = counts_.data() + c * count;
    uint32_t slot = outgoing_start_[c];
    for_each_cross(c, [&](size_t d, CrossPair x) {
      x.slot = slot++;
      incoming_[place[d]++] = x;
    });
  });
}

void SweepChunks::ResetClaims() {
  for (size_t c = 0; c < Count(); ++c) claim_[c].store(kPending, std::memory_order_relaxed);
  ++passes_;
}

}  // namespace demcal::core
