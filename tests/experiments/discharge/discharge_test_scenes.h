#pragma once
// The test grains and the placed-fill funnel the discharge tests share: each test changes only
// what its own question needs (friction, orifice, funnel height), so the common set-up is one.
#include "core/scene/scene.h"
#include "experiments/discharge/discharge_experiment.h"

namespace demcal::test {

// Soft, cohesionless, monodisperse glass-like spheres of diameter d and a wall of the same
// material (materials 0 and 1); every pair takes `pair` (default: μs 0.5, e 0.5, no rolling
// friction).
inline core::Scene GlassBeads(double d_m, double density_kg_m3 = 2500,
                              const core::PairParameters& pair = {}) {
  core::Scene model;
  model.materials = {{"glass", 1.2e6, 0.25, density_kg_m3}, {"wall", 1.2e6, 0.25, density_kg_m3}};
  core::Species beads;
  beads.name = "beads";
  beads.size.diameter_m = d_m;
  model.species = {beads};
  model.pair_parameters.assign(4, pair);
  model.time.rayleigh_fraction = 0.25;
  return model;
}

// `mass_kg` of beads placed in a 30° funnel of top 24 d above the orifice, a catch bin
// 12.5 d deep below, settled to 1e-4 J/kg before the gate opens.
inline objectives::DischargeSettings PlacedFunnel(double d_m, double orifice_m, double mass_kg) {
  objectives::DischargeSettings s;
  s.fill = objectives::DischargeSettings::Fill::kPlace;
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

}  // namespace demcal::test
