#pragma once
// Picture of the heap face (as the paper's Figs. 9 and 14): the grains of the front layer seen
// from the front (−y), drawn as circles coloured by species, with the bin grid of Fig. 8 on top.
// Each grain is drawn by its SurfaceSpheres (clump shapes show), or as its volume-equivalent
// sphere when the snapshot has none; grains nearer the viewer are drawn last.
//
// Default colours follow the paper: BP white/grey, TAED blue, EP red (species 0, 1, 2); pass one
// colour per species otherwise. Usage:
//   HeapFaceSvgOptions o;  o.layers = FrontFace();
//   if (!WriteHeapFaceSvg("out/heap_front.svg", snapshot, *grid, o, &error)) ...
#include <string>
#include <vector>

#include "objectives/metrics/bin_composition.h"
#include "objectives/metrics/heap_bins.h"
#include "objectives/common/snapshot.h"

namespace demcal::objectives {

struct HeapFaceSvgOptions {
  LayerRange layers = FrontFace();  // whose grains are drawn (by centre)
  std::vector<std::string> species_colours = {"#f0f0f0", "#1f5fd6", "#d62728"};
  std::string outline_colour = "#8c8c8c";
  double width_px = 900;  // picture width; the height follows the heap's aspect ratio
  bool draw_grid = true;
};

// The SVG document. Species without a colour in the list are drawn black.
std::string HeapFaceSvg(const Snapshot& snapshot, const HeapBinGrid& grid,
                        const HeapFaceSvgOptions& options);

bool WriteHeapFaceSvg(const std::string& path, const Snapshot& snapshot, const HeapBinGrid& grid,
                      const HeapFaceSvgOptions& options, std::string* error);

}  // namespace demcal::objectives
