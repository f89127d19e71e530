#pragma once
#include <cstdint>
#include <sstream>
#include <string>

namespace demcal::core {

// How evenly the parallel force sweep's chunks (core/neighbours/sweep_chunks.h) shared the work,
// in thread CPU time: each chunk's own pairs and walls, its cross pairs, and any wait for a cross
// pair another chunk is evaluating, but not time the thread lost to other processes, so it reads
// the same on a shared or oversubscribed machine. A pass over C chunks lasts at least its slowest
// chunk: with a core per chunk, the sweep keeps C·slowest of CPU capacity busy for Σ chunk time.
struct SweepBalance {
  int64_t passes = 0;         // force passes run in more than one chunk
  double chunk_cpu_s = 0;     // Σ over passes and chunks
  double capacity_cpu_s = 0;  // Σ over passes of (chunks × the slowest chunk)
  int64_t chunks = 0;         // in the last pass
  double cross_pairs = 0;     // Σ over passes of the listed pairs that cross a chunk boundary
  double listed_pairs = 0;    // Σ over passes of the listed pairs

  SweepBalance& operator-=(const SweepBalance& o) {
    passes -= o.passes, chunk_cpu_s -= o.chunk_cpu_s, capacity_cpu_s -= o.capacity_cpu_s;
    cross_pairs -= o.cross_pairs, listed_pairs -= o.listed_pairs;
    return *this;
  }
  // Σ chunk time / capacity: 1 for even chunks; the sweep's parallel efficiency at one thread
  // per chunk if nothing but the balance limited it (memory bandwidth and scheduling aside).
  double Efficiency() const { return capacity_cpu_s > 0 ? chunk_cpu_s / capacity_cpu_s : 1; }
  // The share of listed pairs that crossed a chunk boundary: evaluated apart from their rows,
  // their result on the row's particle stored and read back (sweep_chunks.h), so they cost more
  // than own pairs.
  double CrossPairShare() const { return listed_pairs > 0 ? cross_pairs / listed_pairs : 0; }
  // "16 chunks, 4000 passes, chunk CPU 9.1 s, balance 0.87, cross pairs 31 %" ("single chunk"
  // without passes).
  std::string Report() const {
    if (passes <= 0) return "single chunk";
    std::ostringstream os;
    os.precision(3);
    os << chunks << " chunks, " << passes << " passes, chunk CPU " << chunk_cpu_s
       << " s, balance " << Efficiency() << ", cross pairs " << 100 * CrossPairShare() << " %";
    return os.str();
  }
};

}  // namespace demcal::core
