#include "core/neighbours/neighbour_list.h"

#include "core/math/bounded_cells.h"
#include "core/math/parallel_passes.h"
#include "core/neighbours/bucket_index.h"
#include "core/neighbours/neighbour_list_search.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>
#include <tbb/parallel_sort.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <utility>

namespace demcal::core {

NeighbourList::Grid NeighbourList::MakeGrid(const Settings& s, const std::vector<Vec3>& x,
                                            size_t moving) const {
  // The grid spans the moving particles' bounding box (within the domain), so a few particles
  // in a large domain, or a stream over a wide frozen base, do not pay for millions of empty
  // cells. Fixed spheres more than a cut-off outside that box can be no one's partner.
  // Minima and maxima are exact in any order: the parallel reduction gives the serial box.
  using Box = std::pair<Vec3, Vec3>;
  const Box box = tbb::parallel_reduce(
      tbb::blocked_range<size_t>(0, moving), Box{s.domain_max_m, s.domain_min_m},
      [&](const auto& range, Box b) {
        for (size_t i = range.begin(); i != range.end(); ++i)
          for (int a = 0; a < 3; ++a) {
            b.first[a] = std::min(b.first[a], x[i][a]);
            b.second[a] = std::max(b.second[a], x[i][a]);
          }
        return b;
      },
      [](Box a, const Box& b) {
        for (int k = 0; k < 3; ++k) {
          a.first[k] = std::min(a.first[k], b.first[k]);
          a.second[k] = std::max(a.second[k], b.second[k]);
        }
        return a;
      });
  return MakeGrid(s, box.first, box.second, moving < x.size(), x.size());
}

NeighbourList::Grid NeighbourList::MakeGrid(const Settings& s, Vec3 lo, Vec3 hi,
                                            bool margin_for_others, size_t particles) const {
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
    if (periodic) lo[a] = s.domain_min_m[a], hi[a] = s.domain_max_m[a];
  }
  const Vec3 extent = hi - lo;
  const double max_cells =
      std::min(1e9, std::max(4096.0, kMaxCellsPerParticle * static_cast<double>(particles)));
  const double cell = CellForAtMost(extent, cutoff, max_cells, CellRounding::kDown);
  g.origin = lo;
  int* dims[3] = {&g.nx, &g.ny, &g.nz};
  for (int a = 0; a < 3; ++a) {
    *dims[a] = static_cast<int>(CellsAlong(extent[a], cell, CellRounding::kDown));
    g.inv_cell[a] = *dims[a] / extent[a];  // cells stretched to tile the span exactly
    // A periodic axis spans the whole period; wrapping needs at least 3 cells (else whole axis).
    g.wrap[a] = s.periodic.IsPeriodic(a) && *dims[a] >= 3;
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
  BucketIndex(cell_of_particle_, cells, cell_start_, cell_particles_);
  cell_particles_.resize(cell_particles_.size() + kGatherRun, 0);
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
  const uint32_t longest = MaxOf(row_start_, 1, size_t{first_fixed_} + 1);
  if (longest + 8 < cap / 4) row_capacity_ = longest + longest / 2 + 8;  // shrink after a dense phase
  InclusivePrefixSum(row_start_);
  partner_.resize(row_start_[n]);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, first_fixed_), [&](const auto& range) {
    for (size_t i = range.begin(); i != range.end(); ++i)
      std::copy_n(row_scratch_.data() + i * cap, row_start_[i + 1] - row_start_[i],
                  partner_.begin() + row_start_[i]);
  });
  return true;
}

void NeighbourList::MarkFixedRows(const Grid& grid) {
  fixed_rows_.assign(static_cast<size_t>(grid.ny) * grid.nz, 0);
  const size_t n = cell_of_particle_.size();
  tbb::parallel_for(tbb::blocked_range<size_t>(first_fixed_, n), [&](const auto& range) {
    for (size_t f = range.begin(); f != range.end(); ++f)
      if (const int c = cell_of_particle_[f]; c >= 0)
        std::atomic_ref<uint8_t>(fixed_rows_[c / grid.nx]).store(1, std::memory_order_relaxed);
  });
}

void NeighbourList::SearchForward(const Grid& grid, const Settings& s,
                                  const std::vector<Vec3>& x, const std::vector<double>& r,
                                  const std::vector<int>* body) {
  const size_t n = x.size();
  MarkFixedRows(grid);
  // Found pairs go to one buffer per block of particles, read back in order: a loose column finds
  // about one pair per particle, and rows of a fixed capacity per particle cost a cache line each
  // to write and to read back (perf, 200,000-sphere pour). Update()'s scratch, free during a
  // build: found_count_[i], the pairs i found (sorted in its block's buffer: the `below` ones with
  // j < i first, then its own); incoming_start_[j], the pairs j < i that some i found, which
  // row j lists.
  std::vector<uint32_t>& below = movers_;
  found_count_.resize(first_fixed_);
  below.resize(first_fixed_);
  incoming_start_.assign(first_fixed_, 0);
  auto incoming = [&](size_t j) { return std::atomic_ref<uint32_t>(incoming_start_[j]); };
  const size_t blocks = (first_fixed_ + kSearchBlock - 1) / kSearchBlock;
  if (block_found_.size() < blocks) block_found_.resize(blocks);
  auto block_range = [&](size_t b) {
    return std::pair{b * kSearchBlock, std::min<size_t>((b + 1) * kSearchBlock, first_fixed_)};
  };
  tbb::parallel_for(tbb::blocked_range<size_t>(0, blocks, 1), [&](const auto& range) {
    for (size_t b = range.begin(); b != range.end(); ++b) {
      std::vector<uint32_t>& found = block_found_[b];
      found.clear();
      const auto [first, last] = block_range(b);
      for (size_t i = first; i != last; ++i) {
        const size_t start = found.size();
        uint32_t lower = 0;
        ForEachForwardCandidate(grid, i, x, r, body, s.skin_m, [&](uint32_t j) {
          found.push_back(j);
          if (j < i) ++lower, incoming(j).fetch_add(1, std::memory_order_relaxed);
        });
        found_count_[i] = static_cast<uint32_t>(found.size() - start);
        below[i] = lower;
        if (found_count_[i] > 1) std::sort(found.begin() + start, found.end());
      }
    }
  });
  // Row i: the partners above i it found, then those below that found it.
  row_start_.assign(n + 1, 0);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, first_fixed_), [&](const auto& range) {
    for (size_t i = range.begin(); i != range.end(); ++i)
      row_start_[i + 1] = found_count_[i] - below[i] + incoming_start_[i];
  });
  InclusivePrefixSum(row_start_);
  partner_.resize(row_start_[n]);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, blocks, 1), [&](const auto& range) {
    for (size_t b = range.begin(); b != range.end(); ++b) {
      const uint32_t* found = block_found_[b].data();
      const auto [first, last] = block_range(b);
      for (size_t i = first; i != last; ++i) {
        uint32_t* own = partner_.data() + row_start_[i];
        for (const uint32_t* end = found + found_count_[i]; found != end; ++found) {
          const uint32_t j = *found;
          if (j > i)
            *own++ = j;
          else  // into a distinct slot at the end of row j (the count down)
            partner_[row_start_[j + 1] - incoming(j).fetch_sub(1, std::memory_order_relaxed)] =
                static_cast<uint32_t>(i);
        }
      }
    }
  });
  // A row that received pairs holds them unordered after its own: sorted, it is the one list.
  tbb::parallel_for(tbb::blocked_range<size_t>(0, first_fixed_), [&](const auto& range) {
    for (size_t i = range.begin(); i != range.end(); ++i)
      if (row_start_[i] + found_count_[i] - below[i] != row_start_[i + 1])
        std::sort(partner_.begin() + row_start_[i], partner_.begin() + row_start_[i + 1]);
  });
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

  if (!s.periodic.Any()) {
    SearchForward(grid, s, x, r, body);
  } else if (!SearchOnce(grid, s, x, r, body)) {
    // Pass 1: count partners per row; pass 2: fill and sort each row.
    row_start_.assign(n + 1, 0);
    tbb::parallel_for(tbb::blocked_range<size_t>(0, first_fixed_), [&](const auto& range) {
      for (size_t i = range.begin(); i != range.end(); ++i) {
        uint32_t count = 0;
        ForEachCandidate<true>(grid, i, x, r, body, s.skin_m, [&](uint32_t) { ++count; });
        row_start_[i + 1] = count;
      }
    });
    const uint32_t longest = MaxOf(row_start_, 1, n + 1);
    row_capacity_ = longest + longest / 2 + 8;  // the next build searches once
    InclusivePrefixSum(row_start_);
    partner_.resize(row_start_[n]);
    tbb::parallel_for(tbb::blocked_range<size_t>(0, first_fixed_), [&](const auto& range) {
      for (size_t i = range.begin(); i != range.end(); ++i) {
        uint32_t k = row_start_[i];
        ForEachCandidate<true>(grid, i, x, r, body, s.skin_m, [&](uint32_t j) { partner_[k++] = j; });
        std::sort(partner_.begin() + row_start_[i], partner_.begin() + row_start_[i + 1]);
      }
    });
  }

  CopyOf(x, reference_position_);
  Finish(s);
}

void NeighbourList::Finish(const Settings& s) {
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

std::vector<uint32_t> NeighbourList::CellOrder(const Settings& s, const std::vector<Vec3>& x,
                                               const std::vector<uint8_t>& swept) const {
  const Grid grid = MakeGrid(s, x, x.size());
  // Cells in rows of whole planes, z slowest, x fastest. The force sweep revisits each sphere
  // when it reaches its partners' rows (Newton's third law adds to both), and the partners in the
  // next plane are a plane's worth of slots away: that span of sphere state must stay in a core's
  // cache. When the plane across z that a swept sphere sits in holds on average more than
  // kMaxPlaneSpheres swept spheres (≈ 140 B of state each: ≈ 630 kB, over half a 1 MB L2
  // cache), the planes lie across the axis with the most cells instead, the smallest planes.
  // On a 190 mm wide, 50 mm deep bed (200,000 spheres) a plane across its height holds ≈ 12,700
  // spheres, one across its width ≈ 3,500: 9 % less CPU time per step; on its 60 mm wide twin
  // (20,000), whose planes all fit, the other order was 3 % slower (docs/performance.md, "Large
  // beds"). Swept spheres are counted, not cells, and averaged over the spheres (Σ n² / Σ n over
  // the planes' counts n) rather than taken at the fullest plane: a pour's column over a wide
  // frozen base spans wide, nearly empty planes (the fixed base is not swept) and packs densely
  // only where it lands; a rule by cells cost its pours 6–9 % (docs/performance.md).
  constexpr int64_t kMaxPlaneSpheres = 4500;
  std::vector<int> cell(x.size());
  tbb::parallel_for(tbb::blocked_range<size_t>(0, x.size()), [&](const auto& range) {
    for (size_t i = range.begin(); i != range.end(); ++i) cell[i] = grid.CellOf(x[i]);
  });
  std::vector<int64_t> per_plane(grid.nz, 0);
  for (size_t i = 0; i < x.size(); ++i)
    if (swept.empty() || swept[i]) ++per_plane[cell[i] / (grid.nx * grid.ny)];
  const int n[3] = {grid.nx, grid.ny, grid.nz};
  int axes[3] = {2, 1, 0};  // slowest first
  double spheres = 0, weighted = 0;
  for (const int64_t count : per_plane)
    spheres += static_cast<double>(count), weighted += static_cast<double>(count) * count;
  if (weighted > kMaxPlaneSpheres * spheres)
    std::stable_sort(axes, axes + 3, [&](int a, int b) { return n[a] > n[b]; });  // ties: z, y, x
  std::vector<std::pair<int64_t, uint32_t>> keyed(x.size());
  tbb::parallel_for(tbb::blocked_range<size_t>(0, x.size()), [&](const auto& range) {
    for (size_t i = range.begin(); i != range.end(); ++i) {
      const int c = cell[i];
      const int at[3] = {c % grid.nx, c / grid.nx % grid.ny, c / grid.nx / grid.ny};
      const int64_t key =
          (int64_t{at[axes[0]]} * n[axes[1]] + at[axes[1]]) * n[axes[2]] + at[axes[2]];
      keyed[i] = {key, static_cast<uint32_t>(i)};
    }
  });
  // The keys are unique (slot i), so any sort gives the one order: parallel where it can be.
  tbb::parallel_sort(keyed.begin(), keyed.end());
  std::vector<uint32_t> order(x.size());
  tbb::parallel_for(tbb::blocked_range<size_t>(0, x.size()), [&](const auto& range) {
    for (size_t k = range.begin(); k != range.end(); ++k) order[k] = keyed[k].second;
  });
  return order;
}

}  // namespace demcal::core
