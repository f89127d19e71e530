#pragma once
// Segregation index of the heap (Alizadeh et al. 2018, section 2.6, Eqs. 5–7): per species and
// per sample region (front face, back face, each depth layer, whole heap), the CoV of the
// species' concentration over the bins that hold grains (CoV_m, Eq. 5), the random-mixture
// reference CoV_r (Eq. 6 by Monte Carlo, random_mixture.h) and S_n = CoV_m/CoV_r (Eq. 7), each by
// number fraction and by mass fraction (the paper's 3D analysis uses mass fractions).
//
// Eq. 6's N per bin:
//   mass basis   — the paper's approximation: the bin's filled volume (grain solid volume / 0.6)
//                  × 0.6 / mean granule volume of the species (partly filled bins get smaller N);
//   number basis — the number of grains in the bin: a random mixture samples that many grains,
//                  each of the species with probability P, so Eq. 6 is exact with this N.
// P is the mean of the bins' fractions (the μ of Eq. 5), as the paper drew around "the mean value
// of the mass fractions".
//
// A species absent from a region (μ = 0) or a region with fewer than two occupied bins has no
// index: `defined` is false and `note` says why; its numbers stay 0, never NaN.
// Pure; deterministic from options.random.seed. Usage:
//   auto heap = AnalyseHeap(*counts, MeanGrainVolumes(snapshot, 3), {}, &error);
//   double s_n_ep_whole = heap->whole.species[2].mass.s_n;
#include <optional>
#include <string>
#include <vector>

#include "objectives/metrics/bin_composition.h"
#include "objectives/metrics/random_mixture.h"

namespace demcal::objectives {

struct SegregationOptions {
  RandomMixtureOptions random;    // CoV_r Monte Carlo: repetitions, seed, normal or binomial draws
  double packing_fraction = 0.6;  // loose random packing of spheres (the paper, after [54])
};

// One species, one concentration basis, one region.
struct SegregationIndex {
  bool defined = false;
  std::string note;          // why it is undefined
  int bins_used = 0;         // bins holding grains
  double mean_fraction = 0;  // μ of Eq. 5 = P of Eq. 6
  double cov_m = 0;          // Eq. 5, sample standard deviation
  double cov_r = 0;          // Eq. 6, mean over the Monte Carlo repetitions
  double cov_r_standard_error = 0;
  double s_n = 0;  // Eq. 7
};

struct SpeciesSegregation {
  int species = 0;
  SegregationIndex number;
  SegregationIndex mass;
};

struct RegionSegregation {
  LayerRange range;
  std::vector<SpeciesSegregation> species;
};

struct HeapSegregation {
  RegionSegregation front;                // 2D, first layer
  RegionSegregation back;                 // 2D, last layer
  RegionSegregation whole;                // 3D, face bins through the full depth
  std::vector<RegionSegregation> layers;  // Fig. 12, layer 0 = front
};

// Mean volume-equivalent grain volume (m³) per species; 0 for a species without grains.
std::vector<double> MeanGrainVolumes(const Snapshot& snapshot, int species_count);

// The indices of one region. Fails only on bad input: granule_volumes_m3 not one per species or
// not positive for a species present in the region, or invalid options.
std::optional<RegionSegregation> AnalyseRegion(const BinCounts& counts, const LayerRange& range,
                                               const std::vector<double>& granule_volumes_m3,
                                               const SegregationOptions& options,
                                               std::string* error);

// Front, back, whole heap and every layer.
std::optional<HeapSegregation> AnalyseHeap(const BinCounts& counts,
                                           const std::vector<double>& granule_volumes_m3,
                                           const SegregationOptions& options, std::string* error);

}  // namespace demcal::objectives
