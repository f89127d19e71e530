#pragma once
// Noise floor of the segregation indices: what CoV_m (Eq. 5) and S_n (Eq. 7) read when the same
// heap is a perfectly random mixture. The grains of the settled heap that lie in a bin keep their
// positions; their identities (species, mass, size) are shuffled among those positions (a uniform
// random permutation, `shuffles` times, seeded), so every bin keeps its grain count and the heap
// keeps its species counts. Each shuffled heap is binned exactly as the measured one, and per
// region, species and basis the floor reports the mean and the central `band` (95 %) interval of
//   CoV_shuffled                      (Eq. 5 on the shuffled heap), and
//   S_n,random = CoV_shuffled / CoV_r  (CoV_r = the measured heap's Eq. 6 reference),
// so a measured S_n inside [s_n_low, s_n_high] is what label noise alone produces at this grain
// count and bin layout: it is not evidence of segregation. With few grains of a species (coarse
// fidelity) the band is wide and its mean can lie well away from 1 (the normal approximation of
// Eq. 6 fails for a handful of grains per bin); the shuffle makes no such approximation.
//
// Pure; deterministic from options.seed. Usage:
//   auto floor = RandomMixtureFloor(analysis.grid, heap, analysis.indices, {}, &error);
//   bool beyond = s_n > floor->whole.species[2].mass.s_n_high;
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "objectives/common/snapshot.h"
#include "objectives/metrics/heap_bins.h"
#include "objectives/metrics/segregation_index.h"

namespace demcal::objectives {

struct SegregationFloorOptions {
  int shuffles = 200;  // Monte Carlo label shuffles, >= 20 (the 2.5 % tail needs some draws)
  uint64_t seed = 1;
  double band = 0.95;  // central probability of the reported interval, in (0, 1)
  bool IsValid(std::string* error) const;
};

// The random-mixture distribution of one index (one species, basis and region).
struct IndexFloor {
  bool defined = false;  // false: no shuffle gave this species a CoV in this region
  int shuffles_used = 0;
  double cov_mean = 0, cov_low = 0, cov_high = 0;
  // Needs the measured index's CoV_r; left 0 when the measured index is undefined.
  bool s_n_defined = false;
  double s_n_mean = 0, s_n_low = 0, s_n_high = 0;
};

struct SpeciesFloor {
  int species = 0;
  IndexFloor number;
  IndexFloor mass;
};

struct RegionFloor {
  LayerRange range;
  std::vector<SpeciesFloor> species;
};

struct HeapFloor {
  RegionFloor front, back, whole;
  std::vector<RegionFloor> layers;  // layer 0 = front
  int grains_shuffled = 0;
};

// The floor for `snapshot` binned by `grid`, with the CoV_r of `measured` (the indices of the same
// snapshot and grid). Fails on invalid options, no grain inside the grid or a species outside
// [0, species count).
std::optional<HeapFloor> RandomMixtureFloor(const HeapBinGrid& grid, const Snapshot& snapshot,
                                            const HeapSegregation& measured,
                                            const SegregationFloorOptions& options,
                                            std::string* error);

}  // namespace demcal::objectives
