#include "objectives/common/replicates.h"

#include <algorithm>
#include <cmath>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "core/math/random.h"
#include "core/math/seed_streams.h"

namespace demcal::objectives {

Summary Summarise(const std::vector<double>& values) {
  Summary s;
  double sum = 0;
  for (double v : values)
    if (std::isfinite(v)) sum += v, ++s.n;
  if (s.n == 0) return s;
  s.mean = sum / s.n;
  if (s.n < 2) return s;
  double ss = 0;
  for (double v : values)
    if (std::isfinite(v)) ss += (v - s.mean) * (v - s.mean);
  s.stddev = std::sqrt(ss / (s.n - 1));
  s.sem = s.stddev / std::sqrt(static_cast<double>(s.n));
  return s;
}

uint64_t ReplicateSeed(uint64_t base_seed, int replicate) {
  return core::DeriveSeed(base_seed, core::kReplicateStreamBase + static_cast<uint64_t>(replicate));
}

int ThreadsPerReplicate(int count, int workers) {
  const int cores = workers > 0 ? workers : tbb::this_task_arena::max_concurrency();
  return std::max(1, cores / std::max(1, count));
}

void RunReplicates(int count, uint64_t base_seed, int workers,
                   const std::function<void(int, uint64_t)>& run) {
  tbb::task_arena arena(workers > 0 ? workers : tbb::task_arena::automatic);
  arena.execute([&] {
    tbb::parallel_for(0, count, 1, [&](int r) { run(r, ReplicateSeed(base_seed, r)); });
  });
}

}  // namespace demcal::objectives
