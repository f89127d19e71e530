#pragma once
// The O(particles) passes of a neighbour rebuild that are not per-particle work: running sums
// (row starts, cell starts), maxima, order checks, copies. Serial, they are a share of each
// rebuild that no thread count shortens, and on a 200,000-sphere pour they bound its 16-thread
// speed-up (docs/performance.md, "Serial passes of a rebuild").
//
// Integer sums, maxima and copies are exact in any order, so each gives the serial result for
// any thread count: determinism is kept. Arrays shorter than kSerialPassBelow run serially (a
// parallel pass's start-up costs more there).
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>
#include <tbb/parallel_scan.h>

#include <algorithm>
#include <cstddef>
#include <limits>
#include <type_traits>
#include <vector>

namespace demcal::core {

inline constexpr size_t kSerialPassBelow = 1 << 14;

// v[k] += v[k − 1] for k = 1 .. v.size() − 1: with v[0] = 0 and v[k + 1] a row's length,
// v becomes the rows' starts.
template <class T>
void InclusivePrefixSum(std::vector<T>& v) {
  static_assert(std::is_integral_v<T>, "exact (order-free) sums only");
  if (v.size() < kSerialPassBelow) {
    for (size_t k = 1; k < v.size(); ++k) v[k] += v[k - 1];
    return;
  }
  tbb::parallel_scan(
      tbb::blocked_range<size_t>(0, v.size(), 4096), T{0},
      [&](const tbb::blocked_range<size_t>& range, T sum, bool final_pass) {
        for (size_t k = range.begin(); k != range.end(); ++k) {
          sum += v[k];
          if (final_pass) v[k] = sum;
        }
        return sum;
      },
      [](T a, T b) { return a + b; });
}

// The largest of v[first .. last) (T's lowest value if empty).
template <class T>
T MaxOf(const std::vector<T>& v, size_t first, size_t last) {
  return tbb::parallel_reduce(
      tbb::blocked_range<size_t>(first, std::max(first, last), 4096),
      std::numeric_limits<T>::lowest(),
      [&](const tbb::blocked_range<size_t>& range, T most) {
        for (size_t k = range.begin(); k != range.end(); ++k) most = std::max(most, v[k]);
        return most;
      },
      [](T a, T b) { return std::max(a, b); });
}

// to = from, element by element in parallel.
template <class T>
void CopyOf(const std::vector<T>& from, std::vector<T>& to) {
  to.resize(from.size());
  if (from.size() < kSerialPassBelow) {
    std::copy(from.begin(), from.end(), to.begin());
    return;
  }
  tbb::parallel_for(tbb::blocked_range<size_t>(0, from.size(), 4096), [&](const auto& range) {
    std::copy(from.begin() + range.begin(), from.begin() + range.end(), to.begin() + range.begin());
  });
}

// Whether v is ascending (each element ≥ the one before), as std::is_sorted.
template <class T>
bool IsAscending(const std::vector<T>& v) {
  if (v.size() < kSerialPassBelow) return std::is_sorted(v.begin(), v.end());
  return tbb::parallel_reduce(
      tbb::blocked_range<size_t>(1, v.size(), 4096), true,
      [&](const tbb::blocked_range<size_t>& range, bool ascending) {
        for (size_t k = range.begin(); ascending && k != range.end(); ++k)
          ascending = !(v[k] < v[k - 1]);
        return ascending;
      },
      [](bool a, bool b) { return a && b; });
}

}  // namespace demcal::core
