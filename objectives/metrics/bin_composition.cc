#include "objectives/metrics/bin_composition.h"

#include <algorithm>
#include <numbers>
#include <numeric>

namespace demcal::objectives {
namespace {

BinComposition EmptyBin(int face, int species_count) {
  BinComposition bin;
  bin.face = face;
  bin.count.assign(species_count, 0);
  bin.mass_kg.assign(species_count, 0.0);
  bin.volume_m3.assign(species_count, 0.0);
  return bin;
}

void Accumulate(BinComposition& into, const BinComposition& from) {
  for (size_t s = 0; s < into.count.size(); ++s) {
    into.count[s] += from.count[s];
    into.mass_kg[s] += from.mass_kg[s];
    into.volume_m3[s] += from.volume_m3[s];
  }
}

double SphereVolumeM3(double radius_m) {
  return 4.0 / 3.0 * std::numbers::pi * radius_m * radius_m * radius_m;
}

}  // namespace

int BinComposition::TotalCount() const { return std::accumulate(count.begin(), count.end(), 0); }
double BinComposition::TotalMassKg() const {
  return std::accumulate(mass_kg.begin(), mass_kg.end(), 0.0);
}
double BinComposition::SolidVolumeM3() const {
  return std::accumulate(volume_m3.begin(), volume_m3.end(), 0.0);
}
double BinComposition::NumberFraction(int species) const {
  const int total = TotalCount();
  return total > 0 ? static_cast<double>(count[species]) / total : 0.0;
}
double BinComposition::MassFraction(int species) const {
  const double total = TotalMassKg();
  return total > 0 ? mass_kg[species] / total : 0.0;
}

LayerRange FrontFace() { return {0, 0, "front"}; }
LayerRange BackFace(int layers) { return {layers - 1, layers - 1, "back"}; }
LayerRange SingleLayer(int layer) { return {layer, layer, "layer " + std::to_string(layer + 1)}; }
LayerRange WholeHeap(int layers) { return {0, layers - 1, "whole"}; }

std::optional<BinCounts> CountGrains(const HeapBinGrid& grid, const Snapshot& snapshot,
                                     int species_count, std::string* error) {
  auto fail = [&](const std::string& message) {
    if (error) *error = "bin composition: " + message;
    return std::nullopt;
  };
  if (species_count < 1) return fail("species_count must be >= 1");
  if (snapshot.grains.empty()) return fail("the snapshot holds no grains");
  BinCounts counts;
  counts.layers = grid.layers();
  counts.face_bins = grid.face_bin_count();
  counts.species_count = species_count;
  for (int layer = 0; layer < counts.layers; ++layer)
    for (int face = 0; face < counts.face_bins; ++face)
      counts.bins.push_back(EmptyBin(face, species_count));
  for (const Grain& g : snapshot.grains) {
    if (g.species < 0 || g.species >= species_count)
      return fail("grain " + std::to_string(g.id) + " has species " + std::to_string(g.species) +
                  ", outside [0, " + std::to_string(species_count) + ")");
    const BinIndex where = grid.Locate(g.position_m);
    if (!where.Inside()) {
      ++counts.outside_count;
      continue;
    }
    BinComposition& bin = counts.bins[where.layer * counts.face_bins + where.face];
    bin.count[g.species] += 1;
    bin.mass_kg[g.species] += g.mass_kg;
    bin.volume_m3[g.species] += SphereVolumeM3(g.radius_m);
  }
  return counts;
}

std::vector<BinComposition> Compose(const BinCounts& counts, const LayerRange& range) {
  std::vector<BinComposition> merged;
  const int first = std::max(range.first, 0);
  const int last = std::min(range.last, counts.layers - 1);
  for (int face = 0; face < counts.face_bins; ++face) {
    merged.push_back(EmptyBin(face, counts.species_count));
    for (int layer = first; layer <= last; ++layer)
      Accumulate(merged.back(), counts.at(layer, face));
  }
  return merged;
}

}  // namespace demcal::objectives
