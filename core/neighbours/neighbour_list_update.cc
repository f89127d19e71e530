// NeighbourList::Update: the incremental rebuild. Invariant (neighbour_list.h): the list holds
// exactly the pairs with |p_i − p_j| < R_i + R_j + skin over the reference positions p. A pair of
// two particles whose references stay put keeps its status, so their rows are kept (minus the
// movers, whose pairs are searched anew around the movers' new references).
//
// Validity: between rebuilds every particle stays within skin/2 of its reference (NeedsRebuild),
// so an unlisted pair is at least R_i + R_j + skin − skin/2 − skin/2 apart: never in contact.
// A kept particle is within refresh_fraction × skin ≤ skin/2 of its reference at the rebuild,
// hence within skin of where it was at that rebuild until the next one. The wall candidates
// (WallContacts) are listed at the reference with a margin of one skin, and a kept particle's
// row is kept with it.
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <functional>

#include "core/math/parallel_passes.h"
#include "core/neighbours/neighbour_list.h"
#include "core/neighbours/neighbour_list_search.h"

namespace demcal::core {

void NeighbourList::Update(const Settings& s, const std::vector<Vec3>& x,
                           const std::vector<double>& r, const std::vector<int>* body,
                           size_t first_fixed, const NeighbourList& previous,
                           double refresh_fraction) {
  const size_t n = x.size();
  const uint32_t fixed_from = static_cast<uint32_t>(std::min(first_fixed, n));
  const bool same_slots =
      previous.reference_position_.size() == n && previous.row_start_.size() == n + 1 &&
      previous.first_fixed_ == fixed_from && previous.half_skin2_ == 0.25 * s.skin_m * s.skin_m &&
      previous.periodic_.origin_m == s.periodic.origin_m &&
      previous.periodic_.length_m == s.periodic.length_m;
  if (!same_slots || !(refresh_fraction > 0 && refresh_fraction <= 0.5)) {
    Build(s, x, r, body, first_fixed);
    return;
  }
  periodic_ = s.periodic;
  first_fixed_ = fixed_from;
  const double refresh2 = refresh_fraction * refresh_fraction * s.skin_m * s.skin_m;
  const std::vector<Vec3>& old_p = previous.reference_position_;
  is_mover_.assign(n, 0);
  const size_t mover_count = tbb::parallel_reduce(
      tbb::blocked_range<size_t>(0, fixed_from), size_t{0},
      [&](const auto& range, size_t movers) {
        for (size_t i = range.begin(); i != range.end(); ++i) {
          is_mover_[i] = Norm2(periodic_.MinimumImage(x[i] - old_p[i])) > refresh2;
          movers += is_mover_[i];
        }
        return movers;
      },
      std::plus<size_t>());
  if (2 * mover_count > fixed_from) {  // most of the bed moved: a full build is cheaper
    Build(s, x, r, body, first_fixed);
    return;
  }
  movers_.clear();
  for (uint32_t i = 0; i < fixed_from; ++i)
    if (is_mover_[i]) movers_.push_back(i);
  last_movers_ = movers_.size();

  // New references for the movers; the grid spans them (others binned within a cut-off).
  CopyOf(old_p, reference_position_);
  Vec3 lo = s.domain_max_m, hi = s.domain_min_m;
  for (uint32_t m : movers_) {
    reference_position_[m] = x[m];
    for (int a = 0; a < 3; ++a) lo[a] = std::min(lo[a], x[m][a]), hi[a] = std::max(hi[a], x[m][a]);
  }
  const std::vector<Vec3>& p = reference_position_;
  const Grid grid = MakeGrid(s, lo, hi, true, n);
  BinParticles(grid, p, 0);

  // Every partner of every mover (both sides, ascending), up to found_capacity_ each; a mover
  // with more sends the search round again with room for it (the result does not depend on it).
  const size_t count = movers_.size();
  found_count_.assign(count, 0);
  for (;;) {
    const uint32_t cap = found_capacity_;
    found_.resize(count * cap);
    const uint32_t longest = tbb::parallel_reduce(
        tbb::blocked_range<size_t>(0, count), uint32_t{0},
        [&](const auto& range, uint32_t most) {
          for (size_t t = range.begin(); t != range.end(); ++t) {
            uint32_t* row = found_.data() + t * cap;
            uint32_t k = 0;
            ForEachCandidate<false>(grid, movers_[t], p, r, body, s.skin_m, [&](uint32_t j) {
              if (k < cap) row[k] = j;
              ++k;
            });
            found_count_[t] = k;
            std::sort(row, row + std::min(k, cap));
            most = std::max(most, k);
          }
          return most;
        },
        [](uint32_t a, uint32_t b) { return std::max(a, b); });
    if (longest <= cap) break;
    found_capacity_ = longest + longest / 2 + 8;
  }
  const uint32_t cap = found_capacity_;

  // Partners gained by kept rows: mover m > i found kept particle i (ascending m per row).
  incoming_start_.assign(n + 1, 0);
  for (size_t t = 0; t < count; ++t)
    for (uint32_t k = 0; k < found_count_[t]; ++k) {
      const uint32_t j = found_[t * cap + k];
      if (j < movers_[t] && !is_mover_[j]) ++incoming_start_[j + 1];
    }
  InclusivePrefixSum(incoming_start_);
  incoming_.resize(incoming_start_[n]);
  {
    std::vector<uint32_t> fill(incoming_start_.begin(), incoming_start_.end() - 1);
    for (size_t t = 0; t < count; ++t)
      for (uint32_t k = 0; k < found_count_[t]; ++k) {
        const uint32_t j = found_[t * cap + k];
        if (j < movers_[t] && !is_mover_[j]) incoming_[fill[j]++] = movers_[t];
      }
  }

  // Row lengths, then rows: a mover's partners above it; a kept row without its movers,
  // merged with the movers that found it.
  std::vector<uint32_t> mover_index(n, 0);  // t + 1 for mover movers_[t]
  for (size_t t = 0; t < count; ++t) mover_index[movers_[t]] = static_cast<uint32_t>(t + 1);
  auto above = [&](size_t t) -> const uint32_t* {
    const uint32_t* row = found_.data() + t * cap;
    return std::upper_bound(row, row + found_count_[t], movers_[t]);
  };
  row_start_.assign(n + 1, 0);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, fixed_from), [&](const auto& range) {
    for (size_t i = range.begin(); i != range.end(); ++i) {
      if (mover_index[i]) {
        const size_t t = mover_index[i] - 1;
        row_start_[i + 1] =
            static_cast<uint32_t>(found_.data() + t * cap + found_count_[t] - above(t));
        continue;
      }
      uint32_t kept = 0;
      for (uint32_t k = previous.row_start_[i]; k < previous.row_start_[i + 1]; ++k)
        kept += !is_mover_[previous.partner_[k]];
      row_start_[i + 1] = kept + incoming_start_[i + 1] - incoming_start_[i];
    }
  });
  InclusivePrefixSum(row_start_);
  partner_.resize(row_start_[n]);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, fixed_from), [&](const auto& range) {
    for (size_t i = range.begin(); i != range.end(); ++i) {
      uint32_t* out = partner_.data() + row_start_[i];
      if (mover_index[i]) {
        const size_t t = mover_index[i] - 1;
        std::copy(above(t), static_cast<const uint32_t*>(found_.data() + t * cap + found_count_[t]),
                  out);
        continue;
      }
      const uint32_t* in = incoming_.data() + incoming_start_[i];
      const uint32_t* in_end = incoming_.data() + incoming_start_[i + 1];
      for (uint32_t k = previous.row_start_[i]; k < previous.row_start_[i + 1]; ++k) {
        const uint32_t j = previous.partner_[k];
        if (is_mover_[j]) continue;
        while (in != in_end && *in < j) *out++ = *in++;
        *out++ = j;
      }
      while (in != in_end) *out++ = *in++;
    }
  });
  Finish(s);
}

bool NeighbourList::CompactFrom(const NeighbourList& previous, const std::vector<uint32_t>& order,
                                size_t first_fixed) {
  const size_t old_n = previous.row_start_.size() - 1;
  const size_t n = order.size();
  if (previous.reference_position_.size() != old_n) return false;
  for (size_t s = 0; s < n; ++s)  // strictly ascending old slots: a compaction, no newcomers
    if (order[s] >= old_n || (s > 0 && order[s] <= order[s - 1])) return false;
  constexpr uint32_t kGone = ~uint32_t{0};  // a removed slot
  new_slot_.assign(old_n, kGone);
  for (size_t s = 0; s < n; ++s) new_slot_[order[s]] = static_cast<uint32_t>(s);
  // The moving part stays in front: new slots below first_fixed were moving, the rest fixed.
  if (first_fixed > n || (first_fixed > 0 && order[first_fixed - 1] >= previous.first_fixed_) ||
      (first_fixed < n && order[first_fixed] < previous.first_fixed_))
    return false;
  reference_position_.resize(n);
  row_start_.assign(n + 1, 0);
  partner_.clear();
  for (size_t s = 0; s < n; ++s) {
    const uint32_t o = order[s];
    reference_position_[s] = previous.reference_position_[o];
    for (uint32_t k = previous.row_start_[o]; k < previous.row_start_[o + 1]; ++k)
      if (const uint32_t j = new_slot_[previous.partner_[k]]; j != kGone) partner_.push_back(j);
    row_start_[s + 1] = static_cast<uint32_t>(partner_.size());
  }
  first_fixed_ = static_cast<uint32_t>(first_fixed);
  half_skin2_ = previous.half_skin2_;
  periodic_ = previous.periodic_;
  return true;
}

}  // namespace demcal::core
