#pragma once
// The scenes of demcal_bench (bench/README.md), sized from the particle count so that the same
// case holds 20,000 or 200,000+ spheres:
//   dense bed  spheres (or rods of spheres) packed as a loose gas into an open box and settled;
//              up to 20,000 spheres the reference 60 × 60 mm box (the LIGGGHTS comparison case),
//              above it a footprint grown as √(N / 20,000), so the loose pack keeps its solid
//              fraction (≈ 15 %; random insertion works up to ≈ 30 %) and the settled bed its
//              depth;
//   pour       spheres d 1.8–2.2 mm onto a frozen rough base (a disc of fixed 2 mm spheres at 2 mm
//              pitch, lifted at random by up to half a radius, as objectives/common/glued_base.cc
//              builds it), either from a narrow stream (the calibration workload) or, with
//              `particles` set, as a column filled at t = 0 just above the base and thrown down
//              onto it: a pour of any size whose particles crowd where the column lands.
#include <cstdint>
#include <vector>

#include "core/scene/scene.h"

namespace demcal::bench {

inline constexpr int64_t kReferenceBedSpheres = 20000;
inline constexpr double kReferenceBedSide_m = 0.06;

struct BedOptions {
  int64_t particles = kReferenceBedSpheres;  // spheres; with clumps, member spheres
  int clump_spheres = 0;                     // 0: plain spheres; N: rods of N spheres
  double cohesion = 0;                       // JKR cohesion number; 0: Hertz–Mindlin
  uint64_t seed = 1;
};

// The open box of the dense bed and the region the loose pack fills.
struct BedBox {
  double side_m = kReferenceBedSide_m;  // square footprint
  double height_m = 0.16;               // box walls; the domain reaches 40 mm higher
  double margin_m = 0.001;              // of the fill region from the walls: the enclosing radius
};

BedBox DenseBedBox(const BedOptions& options);
core::Scene DenseBedScene(const BedOptions& options);

struct PourOptions {
  int threads = 1;
  int64_t steps = 10417;
  int64_t particles = 0;            // 0: the stream; > 0: a column of this many spheres
  double base_radius_m = 0.097;     // 7,384 base spheres; a larger column widens the base
  double mass_rate_kg_s = 0.06;     // ≈ 5,700 spheres/s: 1,500 in the first 10,417 steps
  double stream_height_m = 0.06;    // top of the stream region above the base
  bool keep_fixed_pairs = false;    // the old treatment: fixed spheres swept like moving ones
  double refresh_fraction = 0.25;   // Simulation::Options::neighbour_refresh_fraction
  int balance_probe_chunks = 0;     // Simulation::Options::balance_probe_chunks
  uint64_t seed = 1;
};

// The filled column of a pour of `spheres` spheres of mean volume `mean_volume_m3`: a vertical
// cylinder four radii tall whose loose pack has the dense bed's solid fraction.
struct PourColumn {
  double radius_m = 0;
  double z_lo_m = 0, z_hi_m = 0;  // from just above the base
  double base_radius_m = 0;       // the frozen base: at least twice the column's radius
};

PourColumn PourFillColumn(int64_t spheres, double mean_volume_m3, double min_base_radius_m);
core::Scene PourScene(const PourOptions& options);

}  // namespace demcal::bench
