#include "objectives/metrics/segregation_index.h"

#include <numbers>

#include "core/math/random.h"
#include "core/math/seed_streams.h"
#include "objectives/metrics/coefficient_of_variation.h"

namespace demcal::objectives {
namespace {

enum class Basis { kNumber, kMass };

// Concentrations and Eq. 6's N of the occupied bins for one species and basis.
struct BinSamples {
  std::vector<double> fractions;
  std::vector<double> grains_per_bin;
};

BinSamples Sample(const std::vector<BinComposition>& bins, int species, Basis basis,
                  double granule_volume_m3, double packing) {
  BinSamples samples;
  for (const BinComposition& bin : bins) {
    if (!bin.HoldsGrains()) continue;
    if (basis == Basis::kNumber) {
      samples.fractions.push_back(bin.NumberFraction(species));
      samples.grains_per_bin.push_back(bin.TotalCount());
    } else {
      samples.fractions.push_back(bin.MassFraction(species));
      samples.grains_per_bin.push_back(FilledVolumeM3(bin.SolidVolumeM3(), packing) * packing /
                                       granule_volume_m3);
    }
  }
  return samples;
}

SegregationIndex Index(const BinSamples& samples, const SegregationOptions& options,
                       uint64_t seed) {
  SegregationIndex index;
  index.bins_used = static_cast<int>(samples.fractions.size());
  const auto measured = CoefficientOfVariation(samples.fractions, &index.note);
  if (!measured) return index;
  index.mean_fraction = measured->mean;
  index.cov_m = measured->cov;
  RandomMixtureOptions random = options.random;
  random.seed = seed;
  const auto reference =
      RandomMixtureCoV(measured->mean, samples.grains_per_bin, random, &index.note);
  if (!reference || !(reference->cov_r > 0)) {
    if (reference) index.note = "random mixture: CoV_r is 0 (single-species bins)";
    return index;
  }
  index.cov_r = reference->cov_r;
  index.cov_r_standard_error = reference->standard_error;
  index.s_n = index.cov_m / index.cov_r;
  index.defined = true;
  return index;
}

}  // namespace

std::vector<double> MeanGrainVolumes(const Snapshot& snapshot, int species_count) {
  std::vector<double> sum(species_count, 0.0), count(species_count, 0.0);
  for (const Grain& g : snapshot.grains) {
    if (g.species < 0 || g.species >= species_count) continue;
    sum[g.species] += 4.0 / 3.0 * std::numbers::pi * g.radius_m * g.radius_m * g.radius_m;
    count[g.species] += 1;
  }
  for (int s = 0; s < species_count; ++s) sum[s] = count[s] > 0 ? sum[s] / count[s] : 0.0;
  return sum;
}

std::optional<RegionSegregation> AnalyseRegion(const BinCounts& counts, const LayerRange& range,
                                               const std::vector<double>& granule_volumes_m3,
                                               const SegregationOptions& options,
                                               std::string* error) {
  auto fail = [&](const std::string& message) {
    if (error) *error = "segregation index: " + message;
    return std::nullopt;
  };
  if (!options.random.IsValid(error)) return std::nullopt;
  if (!(options.packing_fraction > 0 && options.packing_fraction <= 1))
    return fail("packing_fraction must lie in (0, 1]");
  if (static_cast<int>(granule_volumes_m3.size()) != counts.species_count)
    return fail("one granule volume per species is needed");
  const std::vector<BinComposition> bins = Compose(counts, range);
  RegionSegregation region{range, {}};
  for (int s = 0; s < counts.species_count; ++s) {
    SpeciesSegregation species{s, {}, {}};
    const uint64_t stream = core::DeriveSeed(options.random.seed,
                                             core::kSpeciesStreamStride * static_cast<uint64_t>(s));
    species.number = Index(Sample(bins, s, Basis::kNumber, 0, 0), options, stream);
    const double volume = granule_volumes_m3[s];
    if (volume > 0) {
      species.mass = Index(Sample(bins, s, Basis::kMass, volume, options.packing_fraction), options,
                           core::DeriveSeed(stream, core::kMassBasisSubstream));
    } else {
      species.mass.note = "no granule volume for species " + std::to_string(s);
      if (species.number.mean_fraction > 0) return fail(species.mass.note);
    }
    region.species.push_back(species);
  }
  return region;
}

std::optional<HeapSegregation> AnalyseHeap(const BinCounts& counts,
                                           const std::vector<double>& granule_volumes_m3,
                                           const SegregationOptions& options, std::string* error) {
  auto analyse = [&](const LayerRange& range) {
    return AnalyseRegion(counts, range, granule_volumes_m3, options, error);
  };
  auto front = analyse(FrontFace());
  auto back = analyse(BackFace(counts.layers));
  auto whole = analyse(WholeHeap(counts.layers));
  if (!front || !back || !whole) return std::nullopt;
  HeapSegregation heap{*front, *back, *whole, {}};
  for (int layer = 0; layer < counts.layers; ++layer) {
    auto region = analyse(SingleLayer(layer));
    if (!region) return std::nullopt;
    heap.layers.push_back(*region);
  }
  return heap;
}

}  // namespace demcal::objectives
