#pragma once
// demcal_bench pour: a poured conical heap — spheres d 1.8–2.2 mm (uniform), ρ = 2500 kg/m³,
// E = 5 MPa, ν = 0.25, e = 0.5, μs = 0.5, μr = 0.1 (epsd2), Δt = 2.4e-5 s, skin 0.5 mm, poured
// from a 5 mm-radius stream onto a frozen rough base (a disc of fixed 2 mm spheres at 2 mm
// pitch, lifted at random by up to half a radius, as objectives/common/glued_base.cc builds it).
// Times --steps steps from the start of the pour and prints where the time went.
#include <CLI/CLI.hpp>

namespace demcal::bench {

struct PourOptions {
  int threads = 1;
  int64_t steps = 10417;
  double base_radius_m = 0.097;    // 7,384 base spheres
  double mass_rate_kg_s = 0.06;    // ≈ 5,700 spheres/s: 1,500 in the first 10,417 steps
  double stream_height_m = 0.06;   // top of the stream region above the base
  bool keep_fixed_pairs = false;   // the old treatment: fixed spheres swept like moving ones
  double refresh_fraction = 0.25;  // Simulation::Options::neighbour_refresh_fraction
  uint64_t seed = 1;
};

CLI::App* AddPourCommand(CLI::App& app, PourOptions* options);
int RunPour(const PourOptions& options);

}  // namespace demcal::bench
