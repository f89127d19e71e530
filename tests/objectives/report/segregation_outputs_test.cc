#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "objectives/report/cov_layer_plot_svg.h"
#include "objectives/report/heap_face_svg.h"
#include "objectives/report/segregation_csv.h"
#include "objectives/metrics/synthetic_heap.h"
#include "core/io/scratch_dir.h"

using namespace demcal::objectives;
using demcal::objectives::testing::MakeHeap;
using demcal::objectives::testing::RandomSpecies;
using demcal::objectives::testing::SyntheticHeap;

namespace {

struct Fixture {
  SyntheticHeap heap;
  Snapshot snap = MakeHeap(heap, 6000, 21, RandomSpecies(0.2, 0.1));
  HeapBinGrid grid = *HeapBinGrid::Create({}, {0.0, heap.width_m, 0.0, heap.height_m}, nullptr);
  BinCounts counts = *CountGrains(grid, snap, 3, nullptr);
  HeapSegregation seg = *AnalyseHeap(counts, MeanGrainVolumes(snap, 3), {}, nullptr);
  std::vector<std::string> names = {"BP", "TAED", "EP"};
};

int Occurrences(const std::string& text, const std::string& what) {
  int n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

std::vector<std::string> Lines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

}  // namespace

TEST_CASE("the bin CSV has one row per layer, bin and species", "[unit]") {
  const Fixture f;
  std::ostringstream out;
  WriteBinCsv(out, f.grid, f.counts, f.names);
  const auto lines = Lines(out.str());
  REQUIRE(lines.size() == 1 + 8 * 21 * 3);
  CHECK(lines[0] ==
        "layer,row,col,x_min_m,x_max_m,z_min_m,z_max_m,y_min_m,y_max_m,species,species_name,"
        "count,mass_kg,solid_volume_m3,number_fraction,mass_fraction");
  // Row 1: front layer, bottom-left bin, species 0 (BP).
  CHECK(lines[1].rfind("0,0,0,0,0.02,0,0.01,0,0.002,0,BP,", 0) == 0);
  int total = 0;
  for (size_t i = 1; i < lines.size(); ++i) {
    std::vector<std::string> cells;
    std::istringstream row(lines[i]);
    for (std::string cell; std::getline(row, cell, ',');) cells.push_back(cell);
    REQUIRE(cells.size() == 16);
    total += std::stoi(cells[11]);
  }
  CHECK(total == 6000 - f.counts.outside_count);
}

TEST_CASE("the index CSV has a row per region, species and basis", "[unit]") {
  const Fixture f;
  std::ostringstream out;
  WriteSegregationCsv(out, f.seg, f.names);
  const auto lines = Lines(out.str());
  REQUIRE(lines.size() == 1 + (3 + 8) * 3 * 2);  // front, back, whole + 8 layers
  CHECK(lines[0].rfind("region,species,species_name,basis,defined,", 0) == 0);
  CHECK(lines[1].rfind("front,0,BP,number,1,21,", 0) == 0);
  CHECK(Occurrences(out.str(), "whole,2,EP,mass,1,") == 1);
  CHECK(Occurrences(out.str(), "nan") == 0);
}

TEST_CASE("the heap face SVG draws the front layer's grains and the 21 bins", "[unit]") {
  const Fixture f;
  int front_grains = 0;
  for (const Grain& g : f.snap.grains) front_grains += f.grid.LayerOf(g.position_m.y) == 0;
  const std::string svg = HeapFaceSvg(f.snap, f.grid, {});
  CHECK(svg.rfind("<svg xmlns=\"http://www.w3.org/2000/svg\"", 0) == 0);
  CHECK(Occurrences(svg, "<circle") == front_grains);
  CHECK(Occurrences(svg, "<rect") == 21 + 1);       // bins + background
  CHECK(Occurrences(svg, "fill=\"#d62728\"") > 0);  // EP red
  CHECK(Occurrences(svg, "fill=\"#1f5fd6\"") > 0);  // TAED blue
  CHECK(Occurrences(svg, "</svg>") == 1);
  HeapFaceSvgOptions back;
  back.layers = BackFace(8);
  back.draw_grid = false;
  CHECK(Occurrences(HeapFaceSvg(f.snap, f.grid, back), "<rect") == 1);
}

TEST_CASE("the CoV-per-layer plot has one line per species", "[unit]") {
  const Fixture f;
  const std::string svg = CovLayerPlotSvg(f.seg, nullptr, f.names, {});
  CHECK(Occurrences(svg, "<polyline") == 3);
  CHECK(Occurrences(svg, "stroke-dasharray") == 3);  // whole-heap CoV per species
  CHECK(Occurrences(svg, ">EP</text>") == 1);
  CHECK(Occurrences(svg, "<circle") == 8 * 3);  // a marker per layer and species
}

TEST_CASE("the CoV-per-layer plot draws the random-mixture band of each species", "[unit]") {
  const Fixture f;
  SegregationFloorOptions options;
  options.shuffles = 30;
  const auto floor = RandomMixtureFloor(f.grid, f.snap, f.seg, options, nullptr);
  REQUIRE(floor);
  const std::string svg = CovLayerPlotSvg(f.seg, &*floor, f.names, {});
  CHECK(Occurrences(svg, "<polygon") == 3);  // one band per species
  CHECK(Occurrences(svg, "fill-opacity") == 3);
  CHECK(Occurrences(svg, "<polyline") == 3);
  CHECK(Occurrences(svg, "band: 95% random") == 1);
  CHECK(Occurrences(CovLayerPlotSvg(f.seg, nullptr, f.names, {}), "<polygon") == 0);
}

TEST_CASE("the granule track CSV has a row per sample with the specific kinetic energy", "[unit]") {
  GranuleTrack track{42, 2, {}};
  track.samples.push_back({0.5, {0.1, 0.0, 0.2}, {0, 0, -2}, 0.001, true, 0.15});
  track.samples.push_back({0.6, {0.1, 0.0, 0.14}, {0, 0, 0}, 0.001, false, 0});
  std::ostringstream out;
  WriteGranuleTracksCsv(out, {track});
  const auto lines = Lines(out.str());
  REQUIRE(lines.size() == 3);
  CHECK(lines[0] ==
        "id,species,time_s,x_m,y_m,z_m,speed_m_s,specific_kinetic_energy_j_kg,surface_height_m,"
        "depth_below_surface_m");
  CHECK(lines[1] == "42,2,0.5,0.1,0,0.2,2,2,0.15,-0.05");  // ½·2² = 2 J/kg
  CHECK(lines[2] == "42,2,0.6,0.1,0,0.14,0,0,,");
}

TEST_CASE("the writers create files and report an unwritable path", "[unit]") {
  const Fixture f;
  const demcal::testing::ScratchDir scratch("segregation_outputs");
  const std::filesystem::path dir = scratch.path();
  std::string error;
  CHECK(WriteBinCsv((dir / "bins.csv").string(), f.grid, f.counts, f.names, &error));
  CHECK(WriteSegregationCsv((dir / "indices.csv").string(), f.seg, f.names, &error));
  CHECK(WriteHeapFaceSvg((dir / "face.svg").string(), f.snap, f.grid, {}, &error));
  CHECK(WriteCovLayerPlotSvg((dir / "cov.svg").string(), f.seg, nullptr, f.names, {}, &error));
  CHECK(std::filesystem::file_size(dir / "face.svg") > 1000);
  CHECK_FALSE(WriteBinCsv("/nonexistent_dir/bins.csv", f.grid, f.counts, f.names, &error));
  CHECK(error.find("/nonexistent_dir/bins.csv") != std::string::npos);
  CHECK_FALSE(
      WriteCovLayerPlotSvg("/nonexistent_dir/cov.svg", f.seg, nullptr, f.names, {}, &error));
  std::filesystem::remove_all(dir);
}
