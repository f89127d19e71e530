#pragma once
// SweepChunks: how the parallel force sweep of ContactForces splits the particle slots into
// contiguous chunks, and which listed pairs cross a chunk boundary.
//
// A pair (i, j), i < j, whose partner j lies in a later chunk than i is a cross pair; it belongs
// to the "incoming" set of j's chunk. Both chunks need its result: j's chunk first (it sums pairs
// from earlier rows before its own), i's chunk only when its sweep reaches row i, usually near
// its end. Each chunk's start (its particles' sums begun, its incoming set evaluated) therefore
// runs once, on demand, by whichever chunk asks first (Ensure): normally the chunk itself as it
// starts, so no barrier separates the evaluation of cross pairs from the sums, and no chunk waits
// unless another is starting exactly the chunk it needs.
//
// Every cross pair has a slot: its rank in entry order over all cross pairs. The pairs of the
// rows of chunk c hold the slots [OutgoingBegin(c), OutgoingBegin(c + 1)), in the order c's sweep
// meets them, so the results that i's chunk reads back lie in one contiguous run.
//
// Only the moving rows [0, list.FirstFixed()) are split: fixed spheres need no force, and a pair
// with a fixed partner is evaluated by its row's chunk alone (never a cross pair).
//
// Balance: Plan() gives every chunk the same modelled work (rows + listed pairs). The sweep also
// reports how long each chunk took (AddTime); Rebalance() then moves the boundaries so that the
// measured times even out, which catches what the model misses (contacts vs mere neighbours,
// walls, a slower core). It keeps what it learnt across a rebuild: each boundary stays at the same
// share of the work, for the particles keep their places in the slot order between rebuilds
// (and a re-sort keeps the spatial order), so a pour, which rebuilds every few steps, is balanced
// by measurement too. Results never depend on where the boundaries lie.
//
// Thread-safety: Plan(), Rebalance() and ResetClaims() are serial; Ensure() and AddTime() (for
// distinct chunks) may be called concurrently.
// Usage:
//   chunks.Plan(list, 4);  ...  chunks.ResetClaims();
//   parallel over c: chunks.Ensure(c, start); sweep chunk c, calling Ensure(d, start) before
//                    reading a cross pair whose partner lies in chunk d.
#include <atomic>
#include <cstdint>
#include <memory>
#include <span>
#include <thread>
#include <vector>

#include "core/math/heap_bytes.h"
#include "core/neighbours/neighbour_list.h"

namespace demcal::core {

class SweepChunks {
 public:
  struct CrossPair {
    uint32_t row = 0;    // particle slot i (in an earlier chunk)
    uint32_t entry = 0;  // neighbour-list entry of (i, j)
    uint32_t slot = 0;   // rank of the entry among all cross pairs
  };

  // Splits `list`'s moving rows into `count` chunks of about equal work (rows + listed pairs)
  // and collects the cross pairs. `count` is clamped to [1, rows].
  void Plan(const NeighbourList& list, size_t count);

  size_t Count() const { return boundary_.size() - 1; }
  uint32_t Begin(size_t c) const { return boundary_[c]; }
  uint32_t End(size_t c) const { return boundary_[c + 1]; }
  size_t CrossPairCount() const { return incoming_.size(); }
  std::span<const CrossPair> Incoming(size_t c) const {
    return {incoming_.data() + incoming_start_[c], incoming_.data() + incoming_start_[c + 1]};
  }
  // The first slot of the cross pairs in chunk c's rows (c = Count(): CrossPairCount()).
  uint32_t OutgoingBegin(size_t c) const { return outgoing_start_[c]; }

  // The cross pairs and per-chunk arrays (core/math/heap_bytes.h).
  size_t HeapBytes() const {
    return VectorBytes(boundary_, share_, incoming_start_, outgoing_start_, counts_, incoming_,
                       time_s_) +
           Count();
  }

  // Adds the measured sweep time of chunk c in this pass.
  void AddTime(size_t c, double seconds) { time_s_[c] += seconds; }
  // After `min_passes` timed passes: if the slowest chunk took more than `tolerance` (relative)
  // longer than the mean, moves each boundary half-way towards where the measured times would
  // be equal (assuming each chunk's time per unit of work stays as measured), restarts the
  // timing and returns true. With a rebuilt `list` (`list_changed`), the boundaries otherwise
  // keep their shares of the work and the timing goes on.
  bool Rebalance(const NeighbourList& list, bool list_changed, int min_passes, double tolerance);

  // Marks every incoming set as not yet evaluated (once per force pass, before the sweep).
  void ResetClaims();  // also counts the passes for Rebalance

  // Returns once `start(c)` has run for chunk c in this pass: runs it here if no other thread
  // has begun it, else waits for the one that has.
  template <class Start>
  void Ensure(size_t c, Start&& start) {
    std::atomic<uint8_t>& state = claim_[c];
    if (state.load(std::memory_order_acquire) == kDone) return;
    uint8_t expected = kPending;
    if (state.compare_exchange_strong(expected, kRunning, std::memory_order_acquire)) {
      start(c);
      state.store(kDone, std::memory_order_release);
      return;
    }
    while (state.load(std::memory_order_acquire) != kDone) std::this_thread::yield();
  }

 private:
  static constexpr uint8_t kPending = 0, kRunning = 1, kDone = 2;
  // Boundaries where the work before a row (rows + pairs) reaches each of `shares` of the total;
  // the timing restarts if `restart_timing`.
  void SplitRows(const NeighbourList& list, const std::vector<double>& shares, bool restart_timing);
  double WorkBefore(const NeighbourList& list, uint32_t row) const {
    return static_cast<double>(list.RowBegin(row)) + row;
  }
  void CollectCrossPairs(const NeighbourList& list);

  std::vector<uint32_t> boundary_{0, 0};   // chunk c is slots [boundary_[c], boundary_[c+1])
  std::vector<double> share_{0, 1};        // the work before each boundary, over the total
  std::vector<uint32_t> incoming_start_;   // chunk c's cross pairs: [start[c], start[c+1])
  std::vector<uint32_t> outgoing_start_;   // slots of the cross pairs in chunk c's rows
  std::vector<uint32_t> counts_;           // CollectCrossPairs' scratch, per pair of chunks
  std::vector<CrossPair> incoming_;
  std::unique_ptr<std::atomic<uint8_t>[]> claim_;  // per chunk: kPending, kRunning or kDone
  std::vector<double> time_s_;                     // per chunk, since the last (re)plan
  int passes_ = 0;
};

}  // namespace demcal::core
