#pragma once
// Line plot of the CoV per depth layer (the paper's Fig. 12): x = layer number (1 = front face),
// y = CoV_m of each species' concentration in that layer, one line per species, with the
// whole-heap CoV as a dashed line of the same colour. Layers where a species has no index are
// left out of its line. With a noise floor (segregation_floor.h), a translucent band per species
// spans, layer by layer, the central 95 % of the CoV a random mixture of the same grains gives:
// a line inside its band is not distinguishable from a random mixture. Hand-written SVG. Usage:
//   WriteCovLayerPlotSvg("out/cov_per_layer.svg", heap, &floor, {"BP", "TAED", "EP"}, {}, &error);
#include <string>
#include <vector>

#include "objectives/metrics/segregation_floor.h"
#include "objectives/metrics/segregation_index.h"

namespace demcal::objectives {

struct CovLayerPlotOptions {
  bool by_mass = true;  // mass fractions (the paper's 3D analysis) or number fractions
  std::vector<std::string> species_colours = {"#7f7f7f", "#1f5fd6", "#d62728"};
  double width_px = 640, height_px = 420;
};

// `species_names` label the legend (index used where a name is missing).
// `floor` may be null (no band).
std::string CovLayerPlotSvg(const HeapSegregation& heap, const HeapFloor* floor,
                            const std::vector<std::string>& species_names,
                            const CovLayerPlotOptions& options);

bool WriteCovLayerPlotSvg(const std::string& path, const HeapSegregation& heap,
                          const HeapFloor* floor,
                          const std::vector<std::string>& species_names,
                          const CovLayerPlotOptions& options, std::string* error);

}  // namespace demcal::objectives
