#include "objectives/metrics/heap_segregation.h"

namespace demcal::objectives {

std::optional<HeapSegregationAnalysis> AnalyseSegregationHeap(
    const Snapshot& snapshot, const HeapBinOptions& bins, int species_count,
    const SegregationOptions& options, const std::optional<HeapExtent>& extent,
    std::string* error) {
  const auto heap_extent = extent ? extent : EstimateHeapExtent(snapshot, error);
  if (!heap_extent) return std::nullopt;
  auto grid = HeapBinGrid::Create(bins, *heap_extent, error);
  if (!grid) return std::nullopt;
  auto counts = CountGrains(*grid, snapshot, species_count, error);
  if (!counts) return std::nullopt;
  auto indices = AnalyseHeap(*counts, MeanGrainVolumes(snapshot, species_count), options, error);
  if (!indices) return std::nullopt;
  return HeapSegregationAnalysis{std::move(*grid), std::move(*counts), std::move(*indices)};
}

}  // namespace demcal::objectives
