#include "objectives/metrics/heap_bins.h"

#include <catch2/catch.hpp>

#include "objectives/metrics/bin_composition.h"
#include "objectives/metrics/synthetic_heap.h"

using namespace demcal::objectives;
using demcal::objectives::testing::MakeHeap;
using demcal::objectives::testing::RandomSpecies;
using demcal::objectives::testing::SyntheticHeap;

namespace {

HeapBinGrid PaperGrid(const HeapExtent& extent) {
  std::string error;
  auto grid = HeapBinGrid::Create(HeapBinOptions{}, extent, &error);
  INFO(error);
  REQUIRE(grid);
  return *grid;
}

}  // namespace

TEST_CASE("the default heap grid is the paper's triangle of 6,5,4,3,2,1 bins", "[unit]") {
  // Alizadeh et al. 2018 Fig. 8: 21 bins over the heap face.
  const HeapBinGrid grid = PaperGrid({0.0, 0.12, 0.0, 0.06});
  REQUIRE(grid.face_bin_count() == 21);
  const double w = 0.02, h = 0.01;
  int index = 0;
  for (int row = 0; row < 6; ++row) {
    for (int col = 0; col < 6 - row; ++col, ++index) {
      const FaceBin& bin = grid.face_bins()[index];
      CHECK(bin.row == row);
      CHECK(bin.col == col);
      CHECK(bin.x_min_m == Approx(row * w / 2 + col * w));
      CHECK(bin.x_max_m - bin.x_min_m == Approx(w));
      CHECK(bin.z_min_m == Approx(row * h));
      CHECK(bin.z_max_m == Approx((row + 1) * h));
    }
  }
  CHECK(grid.layers() == 8);
  CHECK(grid.LayerThicknessM() == Approx(0.002));  // 16 mm box, 8 layers of 2 mm
}

TEST_CASE("a rectangular grid spans every row over the full width", "[unit]") {
  HeapBinOptions options;
  options.row_bins = {4, 4, 2};
  options.rectangular = true;
  std::string error;
  const auto grid = HeapBinGrid::Create(options, {0.0, 0.12, 0.0, 0.06}, &error);
  REQUIRE(grid);
  REQUIRE(grid->face_bin_count() == 10);
  CHECK(grid->face_bins()[9].x_min_m == Approx(0.06));
  CHECK(grid->face_bins()[9].x_max_m == Approx(0.12));
  CHECK(grid->FaceBinOf(0.001, 0.059) == 8);
}

TEST_CASE("every grain of a triangular heap lies in exactly one bin", "[unit]") {
  const SyntheticHeap heap;
  const Snapshot snap = MakeHeap(heap, 3000, 11, RandomSpecies(0.2, 0.1));
  const HeapBinGrid grid = PaperGrid({0.0, heap.width_m, 0.0, heap.height_m});
  for (const Grain& g : snap.grains) {
    int containing = 0;
    for (const FaceBin& bin : grid.face_bins()) {
      containing += g.position_m.x >= bin.x_min_m && g.position_m.x < bin.x_max_m &&
                    g.position_m.z >= bin.z_min_m && g.position_m.z < bin.z_max_m;
    }
    REQUIRE(containing == 1);  // the staircase covers the triangle, bins do not overlap
    const int face = grid.FaceBinOf(g.position_m.x, g.position_m.z);
    REQUIRE(face >= 0);
    const FaceBin& bin = grid.face_bins()[face];
    CHECK((g.position_m.x >= bin.x_min_m && g.position_m.x < bin.x_max_m));
  }
  CHECK(grid.FaceBinOf(0.001, 0.059) == -1);  // above the flank, outside the staircase
  CHECK(grid.FaceBinOf(-0.001, 0.001) == -1);
}

TEST_CASE("the heap extent ignores a few stray grains", "[unit]") {
  SyntheticHeap heap;
  heap.radius_m = 0.001;  // 8000 grains of 2 mm fill the heap at about 0.6 packing
  Snapshot snap = MakeHeap(heap, 8000, 3, RandomSpecies(0.2, 0.1));
  Grain stray = snap.grains.front();
  stray.position_m = {0.5, 0.008, 0.4};  // one grain still falling far away
  snap.grains.push_back(stray);
  std::string error;
  const auto extent = EstimateHeapExtent(snap, &error);
  REQUIRE(extent);
  CHECK(extent->x_left_m == Approx(0.0).margin(0.002));
  CHECK(extent->x_right_m == Approx(heap.width_m).margin(0.002));
  CHECK(extent->z_base_m == Approx(-heap.radius_m).margin(1e-4));
  CHECK(extent->height_m == Approx(heap.height_m).margin(0.004));
  CHECK(extent->height_m < 0.1);  // not the stray grain at 0.4 m
}

TEST_CASE("grains are counted per layer, bin and species", "[unit]") {
  const HeapBinGrid grid = PaperGrid({0.0, 0.12, 0.0, 0.06});
  Snapshot snap;
  // Layer l holds l + 1 grains of species 1 in the bottom-left bin; one grain in the apex bin.
  for (int layer = 0; layer < 8; ++layer) {
    for (int k = 0; k <= layer; ++k) {
      Grain g;
      g.id = static_cast<int64_t>(snap.grains.size());
      g.species = 1;
      g.position_m = {0.005, 0.002 * layer + 0.001, 0.005};
      g.radius_m = 0.0005;
      g.mass_kg = 2e-6;
      snap.grains.push_back(g);
    }
  }
  Grain apex = snap.grains.front();
  apex.species = 0;
  apex.mass_kg = 6e-6;
  apex.position_m = {0.06, 0.015, 0.055};
  snap.grains.push_back(apex);
  std::string error;
  const auto counts = CountGrains(grid, snap, 2, &error);
  REQUIRE(counts);
  CHECK(counts->outside_count == 0);
  for (int layer = 0; layer < 8; ++layer) CHECK(counts->at(layer, 0).count[1] == layer + 1);
  CHECK(counts->at(7, 20).count[0] == 1);
  const auto whole = Compose(*counts, WholeHeap(8));
  CHECK(whole[0].TotalCount() == 36);
  CHECK(whole[0].TotalMassKg() == Approx(72e-6));
  CHECK(whole[20].MassFraction(0) == Approx(1.0));
  CHECK(whole[20].NumberFraction(1) == 0.0);
  const auto front = Compose(*counts, FrontFace());
  CHECK(front[0].count[1] == 1);
  CHECK(front[20].TotalCount() == 0);
  CHECK(Compose(*counts, BackFace(8))[0].count[1] == 8);
  CHECK(front[0].SolidVolumeM3() == Approx(4.0 / 3.0 * 3.14159265 * 1.25e-10));
}

TEST_CASE("bad heap input gives a clear error", "[unit]") {
  std::string error;
  CHECK_FALSE(EstimateHeapExtent(Snapshot{}, &error));
  CHECK(error.find("no grains") != std::string::npos);
  HeapBinOptions zero_layers;
  zero_layers.layers = 0;
  CHECK_FALSE(HeapBinGrid::Create(zero_layers, {0, 1, 0, 1}, &error));
  CHECK(error.find("layers") != std::string::npos);
  CHECK_FALSE(HeapBinGrid::Create(HeapBinOptions{}, {0, 0, 0, 1}, &error));
  const HeapBinGrid grid = PaperGrid({0.0, 0.12, 0.0, 0.06});
  CHECK_FALSE(CountGrains(grid, Snapshot{}, 3, &error));
  Snapshot snap;
  snap.grains.push_back({7, 3, {0.06, 0.001, 0.001}, {}, 0.0005, 1e-6});
  CHECK_FALSE(CountGrains(grid, snap, 3, &error));
  CHECK(error.find("grain 7 has species 3") != std::string::npos);
}
