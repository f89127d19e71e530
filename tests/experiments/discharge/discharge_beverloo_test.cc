// Validation of the funnel-discharge experiment against Beverloo's law.
//
// Beverloo, Leniger & van de Velde (1961), Chem. Eng. Sci. 15:260: the mass flow of coarse
// cohesionless grains out of a flat-bottomed bin through a circular orifice of diameter D is
//   W = C ρ_b √g (D − k d)^{5/2},
// C ≈ 0.58 and k ≈ 1.4 in their data; Nedderman (1992, Statics and Kinematics of Granular
// Materials, Cambridge UP) recommends k ≈ 1.5 for spheres, and 1–2 is the range commonly found.
// The law holds while the orifice, not the container, governs the flow: D well above d, the fill
// above the orifice deeper than about D, the walls some grain diameters from the orifice edge.
// (A 30° cone only 2–5 D wide at the top, as this test used before, is governed by the cone:
// its fitted k fell from ≈ 1.0 for D/d = 5–8 to 0.79 for 5–12 with a poor fit.)
//
// Set-up (all in grain diameters d = 4 mm; friction 0.5, restitution 0.5, no rolling friction,
// no cohesion): a flat-bottomed bin (the experiment's cone at its 89° limit) of diameter D + 12 d,
// orifices D/d = 5, 7, 9.5 and 12, each with two seeds. The fill is placed as a loose lattice and
// settles with the gate closed; ρ_b is measured in it. The flow is fitted only in its steady
// part: from the 350th to the 1000th grain out, with at least 1.2 D of fill still above the
// orifice when the run stops (flat-bottom flow rates stay constant down to a head of about D).
// E = 1.2 MPa (E/(ρ g d) ≈ 1.2·10⁴): ten times stiffer grains changed the flow rates by < 1%
// (0.0856 → 0.0854, 0.194 → 0.194, 0.348 → 0.345 kg/s at D/d = 5, 6.5, 8 in a 30° hopper),
// so the flow is in the stiffness-independent regime. C and k are fitted on the per-orifice
// means. The seeds follow Catch's --rng-seed (base seed 11 + it), so other sets are checked with
//   demcal_tests "discharge: Beverloo*" --rng-seed 1
// k for --rng-seed 0–4: 1.34, 1.31, 1.37, 1.36, 1.27 (C 0.48–0.49, rms residual 1.3–2.9%).
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "objectives/metrics/beverloo.h"
#include "experiments/discharge/discharge_experiment.h"
#include "experiments/discharge/discharge_test_scenes.h"
#include "objectives/common/replicates.h"

using namespace demcal;
using namespace demcal::objectives;

namespace {

constexpr double kD = 0.004, kDensity = 2500, kG = 9.81;
constexpr double kWallGap = 6;              // bin wall to orifice edge, in d
constexpr double kHead = 1.2;               // fill left above the orifice at the stop, in D
constexpr double kSkip = 350, kOut = 1000;  // grains out: start of the fit, end of the run
constexpr int kSeeds = 2;
const std::vector<double> kRatios = {5, 7, 9.5, 12};  // D/d

// Monodisperse glass-like beads and a wall of the same material (μs 0.5, e 0.5, μr 0).
core::Scene Beads() { return test::GlassBeads(kD, kDensity); }

// The bin and fill for orifice D = ratio · d: the head of 1.2 D plus the grains to discharge,
// counted at a solid fraction of 0.63 (the settled fill's, measured ≈ 0.61).
DischargeSettings FlatBin(double ratio) {
  const double bin = (ratio + 2 * kWallGap) * kD;
  const double cells = 1.5 * (bin / kD) * (bin / kD);  // (π/4 B² d) / (π/6 d³)
  const double grains = std::ceil(0.63 * cells * kHead * ratio + kOut);
  // Room the experiment asks for: the fill at a solid fraction of 0.6 in 90% of the bin, the
  // discharged grains in 40% of the catch bin (side 1.5 B); a shallow catch bin keeps the
  // falling grains slow (their speed sets how often the neighbour lists are rebuilt).
  const double fill_height_d = grains / (0.6 * 0.9 * cells);
  const double catch_depth_d = std::max(8.0, kOut / (0.6 * 0.4 * 2.25 * cells));
  const double grain_kg = kDensity * std::numbers::pi / 6 * kD * kD * kD;
  DischargeSettings s;
  s.fill = DischargeSettings::Fill::kPlace;
  s.feed.components = {{0, 1.0}};
  s.feed.mass_kg = grains * grain_kg;
  s.feed.mass_rate_kg_s = 1;
  s.hopper = {.top_diameter_m = bin,
              .orifice_diameter_m = ratio * kD,
              .cone_half_angle_deg = 89,
              .cylinder_height_m = (fill_height_d + 1) * kD};
  s.catch_depth_m = (catch_depth_d + 1) * kD;
  s.wall_material = 1;
  s.settle.specific_kinetic_J_kg = 1e-4;
  s.settle.max_time_s = 2;
  s.sample_interval_s = 0.002;
  s.stall_s = 0.5;
  s.max_discharge_s = 5;
  s.analysis.discharge_fraction = kOut / grains;
  s.analysis.flow_window_low = kSkip / grains;
  s.analysis.flow_window_high = kOut / grains;
  return s;
}

}  // namespace

TEST_CASE("discharge: Beverloo's law with k in [1, 2] from a flat-bottomed bin", "[physics]") {
  const core::Scene model = Beads();
  const uint64_t base_seed = 11 + Catch::rngSeed();
  const int runs = static_cast<int>(kRatios.size()) * kSeeds;
  std::vector<DischargeRun> results(runs);
  for (double ratio : kRatios) {
    std::string error;
    INFO("D/d = " << ratio);
    REQUIRE(FlatBin(ratio).IsValid(model, &error));
  }
  RunReplicates(runs, base_seed, 2, [&](int r, uint64_t seed) {
    results[r] = RunDischarge(model, FlatBin(kRatios[r / kSeeds]), seed, {});
  });
  std::vector<BeverlooPoint> points;
  double bulk_density = 0;
  for (size_t i = 0; i < kRatios.size(); ++i) {
    double flow = 0;
    for (int k = 0; k < kSeeds; ++k) {
      const DischargeRun& run = results[i * kSeeds + k];
      INFO("D/d = " << kRatios[i] << ", seed " << run.seed << ": " << run.status << " "
                    << run.message << " " << run.metrics.message);
      REQUIRE(run.ok());
      std::printf(
          "Beverloo check: D/d = %4.1f  W = %.4f kg/s  rho_b = %.0f kg/m3  "
          "(%d grains, %.1f s wall)\n",
          kRatios[i], run.metrics.mass_flow_kg_s, run.bulk_density_kg_m3,
          static_cast<int>(run.particles), run.wall_time_s);
      flow += run.metrics.mass_flow_kg_s / kSeeds;
      bulk_density += run.bulk_density_kg_m3 / runs;
    }
    points.push_back({kRatios[i] * kD, flow});
  }
  CHECK(bulk_density > 0.55 * kDensity);  // a random packing of spheres, solid fraction ≈ 0.6
  CHECK(bulk_density < 0.66 * kDensity);
  const BeverlooFit fit = FitBeverloo(points, bulk_density, kD, kG);
  std::printf("Beverloo fit (seeds from %llu): C = %.3f  k = %.2f  rms relative residual = %.3f\n",
              static_cast<unsigned long long>(base_seed), fit.C, fit.k, fit.rms_relative_residual);
  INFO(fit.message);
  REQUIRE(fit.ok);
  CHECK(fit.k >= 1.0);
  CHECK(fit.k <= 2.0);
  CHECK(fit.rms_relative_residual < 0.05);
  // The exponent: the least-squares slope of ln W on ln(D − k d) with Nedderman's k = 1.5 held
  // (so the exponent is not fitted together with k, which trades off against it). Exact Beverloo
  // data with a true k anywhere in the common 1–2 give a slope of 2.30–2.74 at these orifices
  // (1.27–1.37, the k fitted above for five seed sets: 2.40–2.45); a 3 % error in the smallest
  // orifice's flow moves it by 0.03. Hence 2.5 ± 0.25; a slot's law (3/2) or a flow set by the
  // fill rather than the orifice (≈ 0) fall far outside.
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (const BeverlooPoint& p : points) {
    const double x = std::log(p.orifice_diameter_m - 1.5 * kD), y = std::log(p.mass_flow_kg_s);
    sx += x, sy += y, sxx += x * x, sxy += x * y;
  }
  const double n = static_cast<double>(points.size());
  const double exponent = (n * sxy - sx * sy) / (n * sxx - sx * sx);
  std::printf("Beverloo exponent with k = 1.5 held: %.3f\n", exponent);
  CHECK(exponent == Approx(2.5).margin(0.25));
}
