#include "objectives/discharge_experiment.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "core/simulation.h"
#include "objectives/beverloo.h"
#include "objectives/hopper_fill.h"
#include "objectives/outflow_recorder.h"

using namespace demcal;
using namespace demcal::objectives;

namespace {

// Soft, cohesionless, monodisperse glass-like spheres of diameter d: two materials (grains,
// wall), friction 0.5, restitution 0.5, no rolling friction.
core::Scene Beads(double d_m) {
  core::Scene model;
  model.materials = {{"glass", 1.2e6, 0.25, 2500}, {"wall", 1.2e6, 0.25, 2500}};
  core::Species beads;
  beads.name = "beads";
  beads.size.diameter_m = d_m;
  model.species = {beads};
  model.pair_parameters.assign(4, core::PairParameters{});
  model.time.rayleigh_fraction = 0.25;
  return model;
}

DischargeSettings Funnel(double d_m, double orifice_m, double mass_kg) {
  DischargeSettings s;
  s.fill = DischargeSettings::Fill::kPlace;
  s.feed.components = {{0, 1.0}};
  s.feed.mass_kg = mass_kg;
  s.feed.mass_rate_kg_s = 1;
  s.hopper = {.top_diameter_m = 24 * d_m, .orifice_diameter_m = orifice_m,
              .cone_half_angle_deg = 30, .cylinder_height_m = 0};
  s.catch_depth_m = 12.5 * d_m;
  s.wall_material = 1;
  s.settle.specific_kinetic_J_kg = 1e-4;
  s.settle.max_time_s = 3;
  s.sample_interval_s = 0.01;
  s.stall_s = 0.5;
  return s;
}

const core::Wall* FindWall(const core::Scene& scene, const std::string& name) {
  for (const core::Wall& w : scene.walls)
    if (w.name == name) return &w;
  return nullptr;
}

}  // namespace

TEST_CASE("discharge scene: funnel on the orifice plane, a closed gate, a catch floor below",
          "[unit]") {
  const double d = 0.002;
  DischargeSettings s = Funnel(d, 0.012, 0.01);
  s.gate_open_s = 0.7;
  s.hopper.cylinder_height_m = 0.01;
  std::string error;
  REQUIRE(s.IsValid(Beads(d), &error));
  const core::Scene scene = BuildDischargeScene(Beads(d), s, 5);
  REQUIRE(scene.IsValid(&error));
  const core::Wall* cone = FindWall(scene, "hopper.cone");
  REQUIRE(cone);
  const auto& frustum = std::get<core::ConeFrustumSurface>(cone->shape);
  CHECK(frustum.height0_m == 0);
  CHECK(frustum.radius0_m == Approx(0.006));
  CHECK(frustum.radius1_m == Approx(12 * d));
  CHECK(frustum.height1_m == Approx((12 * d - 0.006) / std::tan(std::numbers::pi / 6)));
  REQUIRE(FindWall(scene, "hopper.cylinder"));
  const core::Wall* gate = FindWall(scene, "gate");
  REQUIRE(gate);
  CHECK(gate->DisplacementAt(0.69).z == 0);
  CHECK(gate->DisplacementAt(0.71).z < 0);
  // The gate ends below the catch floor, and the grains falling behind it never reach it.
  const double travel = -gate->DisplacementAt(100).z;
  CHECK(travel > s.catch_depth_m);
  CHECK(2 * gate->velocity_m_s.z * gate->velocity_m_s.z / 9.81 > s.catch_depth_m);
  const core::Wall* floor = FindWall(scene, "catch.zmin");
  REQUIRE(floor);
  CHECK(std::get<core::PlaneSurface>(floor->shape).point_m.z == Approx(-s.catch_depth_m));
  CHECK(scene.domain_min_m.z < -s.catch_depth_m);
  REQUIRE(scene.fills.size() == 1);
  CHECK(scene.fills[0].region_min_m.z > s.hopper.TopM());
  CHECK(scene.fills[0].region_max_m.z < scene.domain_max_m.z);

  core::Scene opened = scene;
  OpenGateAt(1.5, &opened);
  CHECK(FindWall(opened, "gate")->DisplacementAt(1.49).z == 0);
  CHECK(FindWall(opened, "gate")->DisplacementAt(100).z == Approx(-travel));
}

TEST_CASE("discharge settings: the orifice must pass 3 of the largest grains", "[unit]") {
  const double d = 0.004;
  std::string error;
  CHECK_FALSE(Funnel(d, 0.011, 0.01).IsValid(Beads(d), &error));
  CHECK(error.find("discharge.hopper.orifice_diameter_m") != std::string::npos);
  CHECK(Funnel(d, 0.013, 0.01).IsValid(Beads(d), &error));
  CHECK_FALSE(Funnel(d, 0.013, 5.0).IsValid(Beads(d), &error));
  CHECK(error.find("discharge.feed.mass_kg") != std::string::npos);
}

TEST_CASE("hopper bulk density: one grain per cubic cell gives mass over cell volume", "[unit]") {
  const HopperGeometry h{.top_diameter_m = 0.1, .orifice_diameter_m = 0.02,
                         .cone_half_angle_deg = 30, .cylinder_height_m = 0.05};
  // A jittered lattice (one grain at a random place in each cell): any region holds on average
  // its volume over a³ grains, so only the cells cut by the probe's boundary add noise.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0, 1);
  core::Particles p;
  const double a = 0.002, m = 1e-5;
  for (double x = -0.05; x < 0.05; x += a)
    for (double y = -0.05; y < 0.05; y += a)
      for (double z = 0; z < h.TopM(); z += a)
        p.Add(static_cast<int64_t>(p.Size()), 0, 0, 0.0005, 1000,
              {x + a * u(rng), y + a * u(rng), z + a * u(rng)}, {}, {});
  for (size_t i = 0; i < p.Size(); ++i) p.mass_kg[i] = m;
  CHECK(HopperBulkDensity(p, h, 0.002) == Approx(m / (a * a * a)).epsilon(0.01));
}

TEST_CASE("outflow recorder: a grain counts once, when its centre first drops below the plane",
          "[unit]") {
  core::Scene scene = Beads(0.002);
  scene.domain_min_m = {-0.1, -0.1, -0.1};
  scene.domain_max_m = {0.1, 0.1, 0.1};
  scene.particles = {{.species = 0, .position_m = {0, 0, 0.01}},
                     {.species = 0, .position_m = {0.01, 0, 0.01}}};
  core::Simulation sim(scene, {.threads = 1});
  std::string error;
  REQUIRE(sim.Initialize(&error));
  OutflowRecorder recorder(1, 0.0);
  recorder.Sample(sim);
  CHECK(recorder.remaining_count() == 2);
  CHECK(recorder.total_out_kg() == 0);
  const double m = sim.particles().mass_kg[0];
  sim.mutable_particles().position_m[0].z = -0.001;
  recorder.Sample(sim);
  sim.mutable_particles().position_m[0].z = 0.001;  // bounced back up
  recorder.Sample(sim);
  sim.mutable_particles().position_m[0].z = -0.002;
  recorder.Sample(sim);
  CHECK(recorder.total_out_kg() == Approx(m));
  CHECK(recorder.remaining_count() == 1);
  REQUIRE(recorder.samples().size() == 4);
  CHECK(recorder.samples()[1].cumulative_mass_kg[0] == Approx(m));
}

// Beverloo, Leniger & van de Velde (1961), Chem. Eng. Sci. 15:260: the mass flow of coarse
// cohesionless grains through an orifice of diameter D is W = C ρ_b √g (D − k d)^{5/2}, with
// k ≈ 1.4–1.5 (between 1 and 2) and C ≈ 0.58 for flat-bottomed bins; a conical hopper changes C
// (a factor of the hopper angle, Rose & Tanaka 1956) but not the (D − k d)^{5/2} scaling.
// Three orifices of 5, 6.5 and 8 grain diameters; ρ_b measured in the settled fill.
// Known weakness (open): this soft, conical set-up gives k near the lower bound. Seed 11 (the
// first tried) fits k = 1.03; seeds 12 and 13 give 0.99 and 0.89, and the 0.1–0.5 flow window
// moves k by ±0.3. Stiffer grains, a flat-bottomed bin and replicates per orifice are the next
// things to try; do not widen the range.
TEST_CASE("discharge: soft cohesionless spheres follow Beverloo's law with k in [1, 2]",
          "[physics]") {
  const double d = 0.004;
  const core::Scene model = Beads(d);
  const double grain_kg = 2500 * std::numbers::pi / 6 * d * d * d;
  std::vector<BeverlooPoint> points;
  double bulk_density = 0;
  for (double ratio : {5.0, 6.5, 8.0}) {
    const DischargeSettings s = Funnel(d, ratio * d, 2000 * grain_kg);
    std::string error;
    REQUIRE(s.IsValid(model, &error));
    const DischargeRun run = RunDischarge(model, s, 11, {});
    INFO("D/d = " << ratio << ": " << run.status << " " << run.message);
    REQUIRE(run.ok());
    std::printf("Beverloo check: D/d = %.1f  W = %.4f kg/s  rho_b = %.0f kg/m3  T = %.2f s  "
                "(%.1f s wall)\n",
                ratio, run.metrics.mass_flow_kg_s, run.bulk_density_kg_m3,
                run.metrics.discharge_time_s, run.wall_time_s);
    points.push_back({ratio * d, run.metrics.mass_flow_kg_s});
    bulk_density += run.bulk_density_kg_m3 / 3;
  }
  CHECK(bulk_density > 0.5 * 2500);  // a random packing of spheres, solid fraction ≈ 0.6
  CHECK(bulk_density < 0.68 * 2500);
  const BeverlooFit fit = FitBeverloo(points, bulk_density, d, 9.81);
  std::printf("Beverloo fit: C = %.3f  k = %.2f  rms relative residual = %.3f\n", fit.C, fit.k,
              fit.rms_relative_residual);
  INFO(fit.message);
  REQUIRE(fit.ok);
  CHECK(fit.k >= 1.0);
  CHECK(fit.k <= 2.0);
  CHECK(fit.rms_relative_residual < 0.05);
}
