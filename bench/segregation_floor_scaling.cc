// demcal_segregation_floor: the random-mixture noise floor of the segregation indices against the
// coarse-graining s, without DEM. For each s it builds a SYNTHETIC random mixture of the
// paper's heap — the feed of examples/segregation_paper.json (BP 425–500 µm 780 kg/m³, TAED
// 850–1000 µm 850 kg/m³, EP 600–700 µm 2320 kg/m³; mass fractions 0.925/0.055/0.02 of 30.85 g),
// diameters × s, each grain's species independent of its place — in the triangular cross-section
// the s = 5 DEM heap measured (base 0.188 m, height 0.055 m; bench/segregation_resolution.sh run
// s5/adhesion/r0), its centre uniform in the triangle and in y ∈ [r, 16 mm − r] (a grain cannot
// sit closer to the wall than its radius). It then bins the heap like the experiment (21 bins × 8
// layers) and prints, per s, the EP grain count, the measured S_n of this random heap and its
// floor (mean and 95 % band of 200 label shuffles) for the whole heap (mass), the front and the
// back face (number). Recipe: re-run with the same --seed for the same table.
//
//   build/bench/demcal_segregation_floor [--seed 1] [--shuffles 200] [--scales 5,3,2,1.5,1]
#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "core/math/random.h"
#include "objectives/metrics/heap_segregation.h"
#include "objectives/metrics/segregation_floor.h"

using namespace demcal;
using namespace demcal::objectives;

namespace {

struct Component {
  double d_min_m, d_max_m, density_kg_m3, mass_fraction;
};
const std::vector<Component> kFeed = {
    {425e-6, 500e-6, 780, 0.925}, {850e-6, 1000e-6, 850, 0.055}, {600e-6, 700e-6, 2320, 0.02}};
constexpr double kMassKg = 0.03085, kBaseM = 0.188, kHeightM = 0.055, kDepthM = 0.016;

// A point uniform in the triangle (base [0, kBaseM] at z = 0, apex at the centre).
core::Vec3 InTriangle(core::Rng& rng, double radius_m) {
  for (;;) {
    const double x = rng.Uniform(0, kBaseM), z = rng.Uniform(0, kHeightM);
    if (z <= kHeightM * (1 - std::abs(x - kBaseM / 2) / (kBaseM / 2)))
      return {x, rng.Uniform(radius_m, kDepthM - radius_m), z};
  }
}

Snapshot RandomHeap(double s, uint64_t seed) {
  core::Rng rng(seed);
  Snapshot heap;
  for (int k = 0; k < static_cast<int>(kFeed.size()); ++k) {
    const Component& c = kFeed[k];
    double mass = 0;
    while (mass < c.mass_fraction * kMassKg) {
      Grain g;
      g.id = static_cast<int64_t>(heap.grains.size());
      g.species = k;
      g.radius_m = s * rng.Uniform(c.d_min_m, c.d_max_m) / 2;
      g.mass_kg = c.density_kg_m3 * 4.0 / 3.0 * std::numbers::pi * std::pow(g.radius_m, 3);
      g.position_m = InTriangle(rng, g.radius_m);
      mass += g.mass_kg;
      heap.grains.push_back(g);
    }
  }
  return heap;
}

void PrintIndex(const SegregationIndex& measured, const IndexFloor& floor) {
  if (!measured.defined || !floor.s_n_defined) {
    std::printf(",,,,");
    return;
  }
  std::printf(",%.4g,%.4g,%.4g,%.4g", measured.s_n, floor.s_n_mean, floor.s_n_low, floor.s_n_high);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"random-mixture noise floor of the segregation indices against coarse-graining"};
  uint64_t seed = 1;
  int shuffles = 200;
  std::vector<double> scales = {5, 3, 2, 1.5, 1};
  app.add_option("--seed", seed, "base seed");
  app.add_option("--shuffles", shuffles, "label shuffles per heap")->check(CLI::Range(20, 100000));
  app.add_option("--scales", scales, "coarse-graining factors")->delimiter(',');
  CLI11_PARSE(app, argc, argv);
  std::printf(
      "# SYNTHETIC random mixtures (recipe: bench/segregation_floor_scaling.cc, seed %llu)\n",
      static_cast<unsigned long long>(seed));
  std::printf(
      "size_scale,grains,ep_grains,s_n_3d,s_n_3d_floor_mean,s_n_3d_floor_low,s_n_3d_floor_high,"
      "s_n_2d_front,s_n_2d_front_floor_mean,s_n_2d_front_floor_low,s_n_2d_front_floor_high,"
      "s_n_2d_back,s_n_2d_back_floor_mean,s_n_2d_back_floor_low,s_n_2d_back_floor_high\n");
  for (double s : scales) {
    if (!(s > 0)) {
      std::fprintf(stderr, "error: --scales: every factor must be > 0, got %g\n", s);
      return 2;
    }
    const Snapshot heap = RandomHeap(s, core::DeriveSeed(seed, static_cast<uint64_t>(s * 100)));
    HeapBinOptions bins;
    bins.y_max_m = kDepthM;
    SegregationOptions options;
    options.random.seed = core::DeriveSeed(seed, 7);
    std::string error;
    const auto a =
        AnalyseSegregationHeap(heap, bins, 3, options, HeapExtent{0, kBaseM, 0, kHeightM}, &error);
    SegregationFloorOptions floor_options;
    floor_options.shuffles = shuffles;
    floor_options.seed = core::DeriveSeed(seed, 11);
    const auto floor =
        a ? RandomMixtureFloor(a->grid, heap, a->indices, floor_options, &error) : std::nullopt;
    if (!floor) {
      std::fprintf(stderr, "error: s = %g: %s\n", s, error.c_str());
      return 1;
    }
    int ep = 0;
    for (const Grain& g : heap.grains) ep += g.species == 2;
    std::printf("%g,%zu,%d", s, heap.grains.size(), ep);
    PrintIndex(a->indices.whole.species[2].mass, floor->whole.species[2].mass);
    PrintIndex(a->indices.front.species[2].number, floor->front.species[2].number);
    PrintIndex(a->indices.back.species[2].number, floor->back.species[2].number);
    std::printf("\n");
    std::fflush(stdout);
  }
  return 0;
}
