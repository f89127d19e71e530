#pragma once
// The whole segregation-heap analysis of one settled snapshot in one call (Alizadeh et al. 2018,
// sections 2.6, 3.1, 3.2): heap extent (estimated, or given), the Fig. 8 bin grid, per-bin
// composition and the indices (CoV_m, CoV_r, S_n per species, by number and by mass) for the front
// face, the back face, every layer and the whole heap. Crop the snapshot to the heap first (no
// funnel or airborne grains). Usage:
//   HeapBinOptions bins;  bins.y_min_m = 0;  bins.y_max_m = 0.016;
//   auto a = AnalyseSegregationHeap(Crop(snap, lo, hi), bins, 3, {}, std::nullopt, &error);
//   a->indices.whole.species[2].mass.s_n;   // EP, 3D (Fig. 13)
#include <optional>
#include <string>

#include "objectives/metrics/bin_composition.h"
#include "objectives/metrics/heap_bins.h"
#include "objectives/metrics/segregation_index.h"

namespace demcal::objectives {

struct HeapSegregationAnalysis {
  HeapBinGrid grid;
  BinCounts counts;
  HeapSegregation indices;
};

// `extent`: nullopt estimates it from the grains (EstimateHeapExtent). Fails with a message on an
// empty snapshot, invalid options or an unknown species.
std::optional<HeapSegregationAnalysis> AnalyseSegregationHeap(
    const Snapshot& snapshot, const HeapBinOptions& bins, int species_count,
    const SegregationOptions& options, const std::optional<HeapExtent>& extent, std::string* error);

}  // namespace demcal::objectives
