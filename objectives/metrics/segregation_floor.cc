#include "objectives/metrics/segregation_floor.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "core/math/random.h"
#include "objectives/metrics/coefficient_of_variation.h"

namespace demcal::objectives {
namespace {

// The CoVs (and S_n) one index took over the shuffles.
struct Draws {
  std::vector<double> cov, s_n;
};

// Per region (front, back, whole, layers...), per species, number then mass basis.
using RegionDraws = std::vector<std::pair<Draws, Draws>>;

std::vector<const RegionSegregation*> Regions(const HeapSegregation& heap) {
  std::vector<const RegionSegregation*> regions = {&heap.front, &heap.back, &heap.whole};
  for (const RegionSegregation& layer : heap.layers) regions.push_back(&layer);
  return regions;
}

// The grains whose centre lies in a bin (spheres dropped: binning uses the centres only).
Snapshot GrainsInBins(const HeapBinGrid& grid, const Snapshot& snapshot) {
  Snapshot inside;
  for (const Grain& g : snapshot.grains)
    if (grid.Locate(g.position_m).Inside()) inside.grains.push_back(g);
  return inside;
}

// Gives every position a uniformly random grain identity (Fisher–Yates over species, mass, size).
void ShuffleIdentities(core::Rng& rng, Snapshot* heap) {
  std::vector<Grain>& g = heap->grains;
  for (size_t i = g.size(); i > 1; --i) {
    const size_t j = std::min(i - 1, static_cast<size_t>(rng.Uniform() * static_cast<double>(i)));
    std::swap(g[i - 1].species, g[j].species);
    std::swap(g[i - 1].mass_kg, g[j].mass_kg);
    std::swap(g[i - 1].radius_m, g[j].radius_m);
  }
}

void Record(const std::vector<double>& fractions, const SegregationIndex& measured, Draws* draws) {
  const auto stats = CoefficientOfVariation(fractions);
  if (!stats) return;
  draws->cov.push_back(stats->cov);
  if (measured.defined && measured.cov_r > 0) draws->s_n.push_back(stats->cov / measured.cov_r);
}

void RecordRegion(const std::vector<BinComposition>& bins, const RegionSegregation& measured,
                  RegionDraws* draws) {
  for (size_t s = 0; s < draws->size() && s < measured.species.size(); ++s) {
    std::vector<double> number, mass;
    for (const BinComposition& bin : bins) {
      if (!bin.HoldsGrains()) continue;
      number.push_back(bin.NumberFraction(static_cast<int>(s)));
      mass.push_back(bin.MassFraction(static_cast<int>(s)));
    }
    Record(number, measured.species[s].number, &(*draws)[s].first);
    Record(mass, measured.species[s].mass, &(*draws)[s].second);
  }
}

// Linear-interpolated quantile q of sorted values.
double Quantile(const std::vector<double>& sorted, double q) {
  const double at = q * static_cast<double>(sorted.size() - 1);
  const size_t lo = static_cast<size_t>(std::floor(at));
  const size_t hi = std::min(lo + 1, sorted.size() - 1);
  return sorted[lo] + (at - static_cast<double>(lo)) * (sorted[hi] - sorted[lo]);
}

// Mean, low and high of the central `band` of the values; false when there are none.
bool Band(std::vector<double> values, double band, double* mean, double* low, double* high) {
  if (values.empty()) return false;
  std::sort(values.begin(), values.end());
  double sum = 0;
  for (double v : values) sum += v;
  *mean = sum / static_cast<double>(values.size());
  *low = Quantile(values, (1 - band) / 2);
  *high = Quantile(values, 1 - (1 - band) / 2);
  return true;
}

IndexFloor Summarise(const Draws& draws, double band) {
  IndexFloor floor;
  floor.shuffles_used = static_cast<int>(draws.cov.size());
  floor.defined = Band(draws.cov, band, &floor.cov_mean, &floor.cov_low, &floor.cov_high);
  floor.s_n_defined = Band(draws.s_n, band, &floor.s_n_mean, &floor.s_n_low, &floor.s_n_high);
  return floor;
}

RegionFloor SummariseRegion(const RegionSegregation& measured, const RegionDraws& draws,
                            double band) {
  RegionFloor region{measured.range, {}};
  for (size_t s = 0; s < draws.size(); ++s)
    region.species.push_back(
        {static_cast<int>(s), Summarise(draws[s].first, band), Summarise(draws[s].second, band)});
  return region;
}

}  // namespace

bool SegregationFloorOptions::IsValid(std::string* error) const {
  std::string problem;
  if (shuffles < 20) problem = "shuffles must be >= 20, got " + std::to_string(shuffles);
  if (!(band > 0 && band < 1)) problem = "band must lie in (0, 1), got " + std::to_string(band);
  if (!problem.empty() && error) *error = "segregation floor: " + problem;
  return problem.empty();
}

std::optional<HeapFloor> RandomMixtureFloor(const HeapBinGrid& grid, const Snapshot& snapshot,
                                            const HeapSegregation& measured,
                                            const SegregationFloorOptions& options,
                                            std::string* error) {
  if (!options.IsValid(error)) return std::nullopt;
  const int species = static_cast<int>(measured.whole.species.size());
  Snapshot heap = GrainsInBins(grid, snapshot);
  if (heap.grains.empty()) {
    if (error) *error = "segregation floor: no grain lies inside the bins";
    return std::nullopt;
  }
  const std::vector<const RegionSegregation*> regions = Regions(measured);
  std::vector<RegionDraws> draws(regions.size(), RegionDraws(species));
  core::Rng rng(options.seed);
  for (int shuffle = 0; shuffle < options.shuffles; ++shuffle) {
    ShuffleIdentities(rng, &heap);
    const auto counts = CountGrains(grid, heap, species, error);
    if (!counts) return std::nullopt;
    for (size_t r = 0; r < regions.size(); ++r)
      RecordRegion(Compose(*counts, regions[r]->range), *regions[r], &draws[r]);
  }
  HeapFloor floor;
  floor.grains_shuffled = static_cast<int>(heap.grains.size());
  floor.front = SummariseRegion(*regions[0], draws[0], options.band);
  floor.back = SummariseRegion(*regions[1], draws[1], options.band);
  floor.whole = SummariseRegion(*regions[2], draws[2], options.band);
  for (size_t r = 3; r < regions.size(); ++r)
    floor.layers.push_back(SummariseRegion(*regions[r], draws[r], options.band));
  return floor;
}

}  // namespace demcal::objectives
