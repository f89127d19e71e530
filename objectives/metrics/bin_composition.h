#pragma once
// Bin composition: per bin of a HeapBinGrid and per species, the number, mass and solid volume of
// the grains whose centre lies in the bin (Alizadeh et al. 2018, section 2.6: the concentrations
// behind Eq. 5). Counting is done once per layer; a LayerRange then merges layers into the sample
// bins of one analysis:
//   2D front face = the first layer (image analysis sees the grains touching the front wall; one
//     2 mm layer is about one particle size, so these are the grains a camera sees),
//   2D back face  = the last layer,
//   one layer     = that layer (the paper's Fig. 12),
//   3D whole heap = every layer, i.e. the face bins extended through the full depth.
//
// Units SI (kg, m³). Plain values; thread-safe to share. Usage:
//   auto counts = CountGrains(grid, snapshot, 3, &error);
//   std::vector<BinComposition> front = Compose(*counts, FrontFace());
#include <optional>
#include <string>
#include <vector>

#include "objectives/metrics/heap_bins.h"
#include "objectives/common/snapshot.h"

namespace demcal::objectives {

// Contents of one sample bin (a face bin over a range of layers).
struct BinComposition {
  int face = 0;                   // index into HeapBinGrid::face_bins()
  std::vector<int> count;         // per species
  std::vector<double> mass_kg;    // per species
  std::vector<double> volume_m3;  // per species: solid volume of the grains
  int TotalCount() const;
  double TotalMassKg() const;
  double SolidVolumeM3() const;  // all species
  // Species fractions; 0 in an empty bin (callers skip empty bins, see HoldsGrains).
  double NumberFraction(int species) const;
  double MassFraction(int species) const;
  bool HoldsGrains() const { return TotalCount() > 0; }
};

// Layers [first, last] (inclusive) merged into one sample bin per face bin.
struct LayerRange {
  int first = 0;
  int last = 0;
  std::string name;  // "front", "back", "layer 3", "whole"
};
LayerRange FrontFace();
LayerRange BackFace(int layers);
LayerRange SingleLayer(int layer);  // named "layer <layer+1>", as the paper counts from 1
LayerRange WholeHeap(int layers);

// Per layer and face bin, the composition (layer-major: at(layer, face)).
struct BinCounts {
  int layers = 0;
  int face_bins = 0;
  int species_count = 0;
  std::vector<BinComposition> bins;  // layers × face_bins
  int outside_count = 0;             // grains whose centre lies in no bin
  const BinComposition& at(int layer, int face) const { return bins[layer * face_bins + face]; }
};

// Tallies every grain of the snapshot into its bin. Fails (nullopt and a message naming the grain)
// on an empty snapshot, species_count < 1 or a grain species outside [0, species_count).
std::optional<BinCounts> CountGrains(const HeapBinGrid& grid, const Snapshot& snapshot,
                                     int species_count, std::string* error);

// One BinComposition per face bin, summed over the layers of `range` (clamped to the grid).
std::vector<BinComposition> Compose(const BinCounts& counts, const LayerRange& range);

}  // namespace demcal::objectives
