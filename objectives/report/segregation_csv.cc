#include "objectives/report/segregation_csv.h"

#include "objectives/report/text_file.h"

namespace demcal::objectives {
namespace {

std::string Name(const std::vector<std::string>& names, int species) {
  return species < static_cast<int>(names.size()) ? names[species] : std::to_string(species);
}

void WriteIndexRows(std::ostream& out, const RegionSegregation& region,
                    const std::vector<std::string>& names) {
  for (const SpeciesSegregation& s : region.species) {
    for (const auto& [basis, index] : {std::pair{"number", &s.number}, {"mass", &s.mass}}) {
      out << region.range.name << ',' << s.species << ',' << Name(names, s.species) << ',' << basis
          << ',' << index->defined << ',' << index->bins_used << ',' << index->mean_fraction << ','
          << index->cov_m << ',' << index->cov_r << ',' << index->cov_r_standard_error << ','
          << index->s_n << '\n';
    }
  }
}

}  // namespace

void WriteBinCsv(std::ostream& out, const HeapBinGrid& grid, const BinCounts& counts,
                 const std::vector<std::string>& species_names) {
  out.precision(10);
  out << "layer,row,col,x_min_m,x_max_m,z_min_m,z_max_m,y_min_m,y_max_m,species,species_name,"
         "count,mass_kg,solid_volume_m3,number_fraction,mass_fraction\n";
  for (int layer = 0; layer < counts.layers; ++layer) {
    const double y_min = grid.y_min_m() + layer * grid.LayerThicknessM();
    for (int face = 0; face < counts.face_bins; ++face) {
      const FaceBin& f = grid.face_bins()[face];
      const BinComposition& bin = counts.at(layer, face);
      for (int s = 0; s < counts.species_count; ++s) {
        out << layer << ',' << f.row << ',' << f.col << ',' << f.x_min_m << ',' << f.x_max_m << ','
            << f.z_min_m << ',' << f.z_max_m << ',' << y_min << ','
            << y_min + grid.LayerThicknessM() << ',' << s << ',' << Name(species_names, s) << ','
            << bin.count[s] << ',' << bin.mass_kg[s] << ',' << bin.volume_m3[s] << ','
            << bin.NumberFraction(s) << ',' << bin.MassFraction(s) << '\n';
      }
    }
  }
}

bool WriteBinCsv(const std::string& path, const HeapBinGrid& grid, const BinCounts& counts,
                 const std::vector<std::string>& species_names, std::string* error) {
  return WriteTextFile(
      path, [&](std::ostream& out) { WriteBinCsv(out, grid, counts, species_names); }, error);
}

void WriteSegregationCsv(std::ostream& out, const HeapSegregation& heap,
                         const std::vector<std::string>& species_names) {
  out.precision(10);
  out << "region,species,species_name,basis,defined,bins_used,mean_fraction,cov_m,cov_r,"
         "cov_r_standard_error,s_n\n";
  for (const RegionSegregation* region : {&heap.front, &heap.back, &heap.whole})
    WriteIndexRows(out, *region, species_names);
  for (const RegionSegregation& layer : heap.layers) WriteIndexRows(out, layer, species_names);
}

bool WriteSegregationCsv(const std::string& path, const HeapSegregation& heap,
                         const std::vector<std::string>& species_names, std::string* error) {
  return WriteTextFile(
      path, [&](std::ostream& out) { WriteSegregationCsv(out, heap, species_names); }, error);
}

void WriteGranuleTracksCsv(std::ostream& out, const std::vector<GranuleTrack>& tracks) {
  out.precision(10);
  out << "id,species,time_s,x_m,y_m,z_m,speed_m_s,specific_kinetic_energy_j_kg,surface_height_m,"
         "depth_below_surface_m\n";
  for (const GranuleTrack& track : tracks) {
    for (const GranuleSample& s : track.samples) {
      out << track.id << ',' << track.species << ',' << s.time_s << ',' << s.position_m.x << ','
          << s.position_m.y << ',' << s.position_m.z << ',' << s.SpeedMS() << ','
          << s.SpecificKineticEnergyJPerKg() << ',';
      if (s.has_surface)
        out << s.surface_height_m << ',' << s.surface_height_m - s.position_m.z;
      else
        out << ',';
      out << '\n';
    }
  }
}

bool WriteGranuleTracksCsv(const std::string& path, const std::vector<GranuleTrack>& tracks,
                           std::string* error) {
  return WriteTextFile(
      path, [&](std::ostream& out) { WriteGranuleTracksCsv(out, tracks); }, error);
}

}  // namespace demcal::objectives
