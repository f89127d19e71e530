#pragma once
// CSV tables of a funnel discharge, SI units in the column names.
//
// Outflow (one row per sample; cumulative mass that has left the funnel, per species):
//   time_s,mass_<species>_kg,...
// Composition (one row per time bin from the gate opening to the discharge end; Fig. 16 of
// Alizadeh et al. 2018):
//   t_start_s,t_end_s,mass_kg,fraction_<species>,...
//
// Usage:
//   if (!WriteOutflowCsv("out/outflow_r0.csv", run.samples, names, &error)) ...
#include <ostream>
#include <string>
#include <vector>

#include "objectives/metrics/discharge_metrics.h"

namespace demcal::objectives {

void WriteOutflowCsv(std::ostream& out, const std::vector<OutflowSample>& samples,
                     const std::vector<std::string>& species_names);
bool WriteOutflowCsv(const std::string& path, const std::vector<OutflowSample>& samples,
                     const std::vector<std::string>& species_names, std::string* error);

void WriteCompositionCsv(std::ostream& out, const std::vector<CompositionBin>& bins,
                         const std::vector<std::string>& species_names);
bool WriteCompositionCsv(const std::string& path, const std::vector<CompositionBin>& bins,
                         const std::vector<std::string>& species_names, std::string* error);

}  // namespace demcal::objectives
