#pragma once
// Pictures of a funnel discharge: the mass out against time since the gate opened, with the fitted
// steady flow, and the outflow composition per species over time (as the paper's Fig. 16,
// Alizadeh et al. 2018). Masses drawn in g, times in s.
//
//   WriteSvg(dir + "/discharge_mass.svg", DischargeMassPlot(samples, t0, m, names), &error);
//   WriteSvg(dir + "/discharge_composition.svg", DischargeCompositionPlot(m, t0, names), &error);
#include <string>
#include <vector>

#include "objectives/metrics/discharge_metrics.h"
#include "objectives/report/svg_plot.h"

namespace demcal::objectives {

// Total and per-species cumulative mass out [g] vs t − gate_open_s [s], and the fitted line.
// species_names may be shorter than the species (missing names become "species k").
SvgPlot DischargeMassPlot(const std::vector<OutflowSample>& samples, double gate_open_s,
                          const DischargeMetrics& metrics,
                          const std::vector<std::string>& species_names);

// Mass fraction per species in each composition bin (a step line) vs t − gate_open_s [s].
SvgPlot DischargeCompositionPlot(const DischargeMetrics& metrics, double gate_open_s,
                                 const std::vector<std::string>& species_names);

}  // namespace demcal::objectives
