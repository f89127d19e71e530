#pragma once
// Replicates: a stochastic experiment (repose angle, CoV) repeated with different seeds, run
// side by side (one simulation per core, each single-threaded: small DEM runs scale better that
// way than one run on many threads), and summarised as mean ± standard error.
//
// Seeds: replicate r uses DeriveSeed(base_seed, kReplicateStreamBase + r)
// (core/math/seed_streams.h), the same for every candidate parameter set (common random numbers),
// so differences between candidates are not packing noise.
#include <cstdint>
#include <functional>
#include <vector>

namespace demcal::objectives {

struct Summary {
  int n = 0;           // finite values summarised
  double mean = 0;
  double stddev = 0;   // sample standard deviation (n − 1); 0 for n < 2
  double sem = 0;      // standard error of the mean, stddev / √n
};

// Mean, sample standard deviation and standard error of the finite values.
Summary Summarise(const std::vector<double>& values);

// The seed of replicate r.
uint64_t ReplicateSeed(uint64_t base_seed, int replicate);

// Threads each of `count` side-by-side simulations gets on `workers` cores (0: all): 1 when the
// replicates fill the cores, else the cores shared out (⌊workers / count⌋), since results do not
// depend on the thread count and an idle core is wasted wall time.
int ThreadsPerReplicate(int count, int workers);

// Calls run(r, ReplicateSeed(base_seed, r)) for r = 0..count−1 on up to `workers` threads
// (0: all cores); returns when all are done. `run` must be thread-safe across replicates.
void RunReplicates(int count, uint64_t base_seed, int workers,
                   const std::function<void(int, uint64_t)>& run);

}  // namespace demcal::objectives
