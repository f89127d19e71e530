// The parallel passes of a rebuild (core/math/parallel_passes.h) give the serial result at
// any thread count, on arrays below and above the length from which they run in parallel.
#include <tbb/task_arena.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <cstdint>
#include <numeric>
#include <random>
#include <vector>

#include "core/math/parallel_passes.h"

using namespace demcal::core;

TEST_CASE("parallel running sums, maxima, copies and order checks are the serial ones",
          "[unit][determinism]") {
  for (const size_t length : {size_t{0}, size_t{1}, size_t{1000}, size_t{200'003}}) {
    std::mt19937 rng(static_cast<unsigned>(length));
    std::uniform_int_distribution<uint32_t> draw(0, 40);
    std::vector<uint32_t> v(length);
    for (uint32_t& x : v) x = draw(rng);
    std::vector<uint32_t> sums(length);
    std::partial_sum(v.begin(), v.end(), sums.begin());
    const uint32_t most = length > 1 ? *std::max_element(v.begin() + 1, v.end()) : 0;
    for (const int threads : {1, 4}) {
      INFO(length << " elements, " << threads << " threads");
      tbb::task_arena arena(threads);
      arena.execute([&] {
        std::vector<uint32_t> scanned = v;
        InclusivePrefixSum(scanned);
        CHECK(scanned == sums);
        CHECK(MaxOf(v, 1, length) == most);
        std::vector<uint32_t> copy{1, 2, 3};
        CopyOf(v, copy);
        CHECK(copy == v);
        CHECK(IsAscending(sums));
        if (length > 2) {
          std::vector<uint32_t> broken = sums;
          broken[length / 2] = broken[length / 2 - 1] + 100;  // one descent after it
          CHECK(IsAscending(broken) == std::is_sorted(broken.begin(), broken.end()));
          broken.back() = 0;
          broken.front() = 1;
          CHECK_FALSE(IsAscending(broken));
        }
      });
    }
  }
}
