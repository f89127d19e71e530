#include "core/neighbours/neighbour_list.h"

#include "core/neighbours/neighbour_list_search.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace demcal::core {

NeighbourList::Grid NeighbourList::MakeGrid(const Settings& s, const std::vector<Vec3>& x,
                                            size_t moving) const {
  // The grid spans the moving particles' bounding box (within the domain), so a few particles
  // in a large domain, or a stream over a wide frozen base, do not pay for millions of empty
  // cells. Fixed spheres more than a cut-off outside that box can be no one's partner.
  Vec3 lo = s.domain_max_m, hi = s.domain_min_m;
  for (size_t i = 0; i < moving; ++i)
    for (int a = 0; a < 3; ++a) lo[a] = std::min(lo[a], x[i][a]), hi[a] = std::max(hi[a], x[i][a]);
  return MakeGrid(s, lo, hi, moving < x.size());
}

NeighbourList::Grid NeighbourList::MakeGrid(const Settings& s, Vec3 lo, Vec3 hi,
                                            bool margin_for_others) const {
  // A cell is at least the largest possible cut-off, so partners lie in the 27 nearest cells.
  const double cutoff = 2.0 * s.max_radius_m + s.skin_m;
  Grid g;
  const double margin = margin_for_others ? cutoff : 0;
  for (int a = 0; a < 3; ++a) {
    const bool periodic = s.periodic.IsPeriodic(a);
    g.reach_lo[a] = periodic ? -std::numeric_limits<double>::infinity() : lo[a] - cutoff;
    g.reach_hi[a] = periodic ? std::numeric_limits<double>::infinity() : hi[a] + cutoff;
    lo[a] = std::max(lo[a] - margin, s.domain_min_m[a]);
    hi[a] = std::min(hi[a] + margin, s.domain_max_m[a]);
    if (!(hi[a] - lo[a] >= cutoff)) hi[a] = lo[a] + cutoff;  // also catches NaN and empty sets
    // A periodic axis spans the whole period; wrapping needs at least 3 cells (else whole axis).
    g.wrap[a] = periodic && static_cast<int>(s.periodic.length_m[a] / cutoff) >= 3;
    if (periodic) lo[a] = s.domain_min_m[a], hi[a] = s.domain_max_m[a];
  }
  const Vec3 extent = hi - lo;
  g.origin = lo;
  int* dims[3] = {&g.nx, &g.ny, &g.nz};
  for (int a = 0; a < 3; ++a) {
    *dims[a] = std::max(1, static_cast<int>(extent[a] / cutoff));
    g.inv_cell[a] = *dims[a] / extent[a];  // cells stretched to tile the span exactly
  }
  return g;
}

void NeighbourList::BinParticles(const Grid& grid, const std::vector<Vec3>& x, size_t moving) {
  const size_t n = x.size();
  const size_t cells = static_cast<size_t>(grid.nx) * grid.ny * grid.nz;
  cell_of_particle_.resize(n);
  auto within_reach = [&](const Vec3& p) {
    return p.x >= grid.reach_lo.x && p.y >= grid.reach_lo.y && p.z >= grid.reach_lo.z &&
           p.x <= grid.reach_hi.x && p.y <= grid.reach_hi.y && p.z <= grid.reach_hi.z;
  };
  tbb::parallel_for(tbb::blocked_range<size_t>(0, n), [&](const auto& range) {
    for (size_t i = range.begin(); i != range.end(); ++i)
      cell_of_particle_[i] = i < moving || within_reach(x[i]) ? grid.CellOf(x[i]) : -1;
  });
  cell_start_.assign(cells + 1, 0);
  for (size_t i = 0; i < n; ++i) cell_start_[cell_of_particle_[i] + 1] += cell_of_particle_[i] >= 0;
  for (size_t c = 0; c < cells; ++c) cell_start_[c + 1] += cell_start_[c];
  cell_particles_.resize(cell_start_[cells]);
  std::vector<uint32_t> fill(cell_start_.begin(), cell_start_.end() - 1);
  for (size_t i = 0; i < n; ++i)
    if (cell_of_particle_[i] >= 0) cell_particles_[fill[cell_of_particle_[i]]++] = i;
}

bool NeighbourList::SearchOnce(const Grid& grid, const Settings& s, const std::vector<Vec3>& x,
                               const std::vector<double>& r, const std::vector<int>* body) {
  const size_t n = x.size();
  const uint32_t cap = row_capacity_;
  if (static_cast<double>(first_fixed_) * cap > 4e8) return false;  // scratch beyond 1.6 GB
  row_scratch_.resize(static_cast<size_t>(first_fixed_) * cap);
  row_start_.assign(n + 1, 0);
  const bool fits = tbb::parallel_reduce(
      tbb::blocked_range<size_t>(0, first_fixed_), true,
      [&](const auto& range, bool ok) {
        for (size_t i = range.begin(); ok && i != range.end(); ++i) {
          uint32_t* row = row_scratch_.data() + i * cap;
          uint32_t count = 0;
          ForEachCandidate<true>(grid, i, x, r, body, s.skin_m, [&](uint32_t j) {
            if (count < cap) row[count] = j;
            ++count;
          });
          ok = count <= cap;
          row_start_[i + 1] = count;
          std::sort(row, row + std::min(count, cap));
        }
        return ok;
      },
      [](bool a, bool b) { return a && b; });
  if (!fits) return false;
  uint32_t longest = 0;
  for (size_t i = 0; i < first_fixed_; ++i) longest = std::max(longest, row_start_[i + 1]);
  if (longest + 8 < cap / 4) row_capacity_ = longest + longest / 2 + 8;  // shrink after a dense phase
  for (size_t i = 0; i < n; ++i) row_start_[i + 1] += row_start_[i];
  partner_.resize(row_start_[n]);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, first_fixed_), [&](const auto& range) {
    for (size_t i = range.begin(); i != range.end(); ++i)
      std::copy_n(row_scratch_.data() + i * cap, row_start_[i + 1] - row_start_[i],
                  partner_.begin() + row_start_[i]);
  });
  return true;
}

void NeighbourList::Build(const Settings& s, const std::vector<Vec3>& x,
                          const std::vector<double>& r, const std::vector<int>* body,
                          size_t first_fixed) {
  const size_t n = x.size();
  periodic_ = s.periodic;
  first_fixed_ = static_cast<uint32_t>(std::min(first_fixed, n));  // fixed rows stay empty
  last_movers_ = first_fixed_;
  const Grid grid = MakeGrid(s, x, first_fixed_);
  BinParticles(grid, x, first_fixed_);

  if (!SearchOnce(grid, s, x, r, body)) {
    // Pass 1: count partners per row; pass 2: fill and sort each row.
    row_start_.assign(n + 1, 0);
    tbb::parallel_for(tbb::blocked_range<size_t>(0, first_fixed_), [&](const auto& range) {
      for (size_t i = range.begin(); i != range.end(); ++i) {
        uint32_t count = 0;
        ForEachCandidate<true>(grid, i, x, r, body, s.skin_m, [&](uint32_t) { ++count; });
        row_start_[i + 1] = count;
      }
    });
    uint32_t longest = 0;
    for (size_t i = 0; i < n; ++i) longest = std::max(longest, row_start_[i + 1]);
    row_capacity_ = longest + longest / 2 + 8;  // the next build searches once
    for (size_t i = 0; i < n; ++i) row_start_[i + 1] += row_start_[i];
    partner_.resize(row_start_[n]);
    tbb::parallel_for(tbb::blocked_range<size_t>(0, first_fixed_), [&](const auto& range) {
      for (size_t i = range.begin(); i != range.end(); ++i) {
        uint32_t k = row_start_[i];
        ForEachCandidate<true>(grid, i, x, r, body, s.skin_m, [&](uint32_t j) { partner_[k++] = j; });
        std::sort(partner_.begin() + row_start_[i], partner_.begin() + row_start_[i + 1]);
      }
    });
  }

  reference_position_ = x;
  Finish(s);
}

void NeighbourList::Finish(const Settings& s) {
  const size_t n = row_start_.size() - 1;
  // Reverse index: for each j, the entries (in ascending order) whose partner is j.
  reverse_start_.assign(n + 1, 0);
  for (uint32_t j : partner_) ++reverse_start_[j + 1];
  for (size_t j = 0; j < n; ++j) reverse_start_[j + 1] += reverse_start_[j];
  reverse_entry_.resize(partner_.size());
  std::vector<uint32_t> fill(reverse_start_.begin(), reverse_start_.end() - 1);
  for (uint32_t k = 0; k < partner_.size(); ++k) reverse_entry_[fill[partner_[k]]++] = k;
  half_skin2_ = 0.25 * s.skin_m * s.skin_m;
  ++builds_;
}

bool NeighbourList::NeedsRebuild(const std::vector<Vec3>& x) const {
  if (periodic_.Any()) return NeedsRebuild(x, periodic_);
  if (x.size() != reference_position_.size()) return true;
  return tbb::parallel_reduce(
      tbb::blocked_range<size_t>(0, first_fixed_), false,  // fixed spheres never move
      [&](const auto& range, bool found) {
        for (size_t i = range.begin(); i != range.end() && !found; ++i)
          found = Norm2(x[i] - reference_position_[i]) > half_skin2_;
        return found;
      },
      [](bool a, bool b) { return a || b; }, tbb::static_partitioner());
}

bool NeighbourList::NeedsRebuild(const std::vector<Vec3>& x, const PeriodicBox& box) const {
  if (x.size() != reference_position_.size()) return true;
  return tbb::parallel_reduce(
      tbb::blocked_range<size_t>(0, first_fixed_), false,
      [&](const auto& range, bool found) {
        for (size_t i = range.begin(); i != range.end() && !found; ++i)
          found = Norm2(box.MinimumImage(x[i] - reference_position_[i])) > half_skin2_;
        return found;
      },
      [](bool a, bool b) { return a || b; });
}

int64_t NeighbourList::Find(uint32_t i, uint32_t j) const {
  if (i + 1 >= row_start_.size()) return -1;
  const auto begin = partner_.begin() + row_start_[i];
  const auto end = partner_.begin() + row_start_[i + 1];
  const auto it = std::lower_bound(begin, end, j);
  return (it != end && *it == j) ? (it - partner_.begin()) : -1;
}

std::vector<uint32_t> NeighbourList::CellOrder(const Settings& s,
                                               const std::vector<Vec3>& x) const {
  const Grid grid = MakeGrid(s, x, x.size());
  std::vector<std::pair<int, uint32_t>> keyed(x.size());
  for (uint32_t i = 0; i < x.size(); ++i) keyed[i] = {grid.CellOf(x[i]), i};
  std::sort(keyed.begin(), keyed.end());
  std::vector<uint32_t> order(x.size());
  for (size_t k = 0; k < x.size(); ++k) order[k] = keyed[k].second;
  return order;
}

}  // namespace demcal::core
