#pragma once
// CSV tables of the segregation heap, SI units in the column names.
//
// Per bin (one row per layer, face bin and species; layer 0 = front face, row 0 = bottom row):
//   layer,row,col,x_min_m,x_max_m,z_min_m,z_max_m,y_min_m,y_max_m,species,species_name,count,
//   mass_kg,solid_volume_m3,number_fraction,mass_fraction
// number_fraction and mass_fraction are of the whole bin (all species); 0 in an empty bin.
//
// Indices (one row per region, species and basis; region = front, back, whole, layer 1..L):
//   region,species,species_name,basis,defined,bins_used,mean_fraction,cov_m,cov_r,
//   cov_r_standard_error,s_n
// basis is "number" or "mass"; an undefined index has defined = 0 and zeros.
//
// Tracked granules (Fig. 19; one row per granule and snapshot; surface columns empty when no
// surface sphere lies in the granule's column):
//   id,species,time_s,x_m,y_m,z_m,speed_m_s,specific_kinetic_energy_j_kg,surface_height_m,
//   depth_below_surface_m
//
// Usage:
//   if (!WriteBinCsv("out/segregation_bins.csv", *grid, *counts, names, &error)) ...
#include <ostream>
#include <string>
#include <vector>

#include "objectives/metrics/bin_composition.h"
#include "objectives/metrics/granule_tracking.h"
#include "objectives/metrics/heap_bins.h"
#include "objectives/metrics/segregation_index.h"

namespace demcal::objectives {

void WriteBinCsv(std::ostream& out, const HeapBinGrid& grid, const BinCounts& counts,
                 const std::vector<std::string>& species_names);
bool WriteBinCsv(const std::string& path, const HeapBinGrid& grid, const BinCounts& counts,
                 const std::vector<std::string>& species_names, std::string* error);

void WriteSegregationCsv(std::ostream& out, const HeapSegregation& heap,
                         const std::vector<std::string>& species_names);
bool WriteSegregationCsv(const std::string& path, const HeapSegregation& heap,
                         const std::vector<std::string>& species_names, std::string* error);

void WriteGranuleTracksCsv(std::ostream& out, const std::vector<GranuleTrack>& tracks);
bool WriteGranuleTracksCsv(const std::string& path, const std::vector<GranuleTrack>& tracks,
                           std::string* error);

}  // namespace demcal::objectives
