// The Rayleigh time step (docs/physics.md §1.5): Δt_R = π R √(ρ/G) / (0.1631 ν + 0.8766) with R
// the smallest sphere that touches, a clump's member included (LIGGGHTS
// fix_check_timestep_gran takes each sphere's own radius).
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

#include "core/scene/scene.h"

using namespace demcal::core;

namespace {

// Glass, E = 48 GPa, ν = 0.2, ρ = 2800 kg/m³: the example of docs/physics.md §1.5.
Scene Glass(double diameter_m) {
  Scene s;
  s.materials = {{"glass", 48e9, 0.2, 2800}};
  s.species = {{"grain", 0, {}, {}}};
  s.species[0].size.diameter_m = diameter_m;
  s.pair_parameters = {PairParameters{}};
  return s;
}

}  // namespace

TEST_CASE("Rayleigh time of a sphere: the formula and the worked example", "[core][timestep]") {
  const double g = 48e9 / (2 * 1.2);
  const double expected = std::numbers::pi * 1e-3 * std::sqrt(2800 / g) / (0.1631 * 0.2 + 0.8766);
  CHECK(RayleighTime(Glass(0.002)) == Approx(expected).epsilon(1e-12));
  CHECK(RayleighTime(Glass(0.002)) == Approx(1.293e-6).epsilon(1e-3));  // physics.md §1.5
}

TEST_CASE("Rayleigh time of a clump: its smallest member sphere, not its equivalent sphere",
          "[core][timestep]") {
  // Two touching equal spheres: the union is exactly twice one sphere's volume, so the
  // equivalent-volume diameter d holds members of diameter d / 2^(1/3).
  Scene pair = Glass(0.002);
  pair.species[0].clump_shape = {{{-0.5, 0, 0}, 0.5}, {{0.5, 0, 0}, 0.5}};
  CHECK(RayleighTime(pair) == Approx(RayleighTime(Glass(0.002)) / std::cbrt(2.0)).epsilon(1e-9));
  // Unequal members: the smaller one sets the step. Touching spheres of radii 1 and 0.5 have
  // the volume (4π/3)(1 + 1/8): the equivalent diameter 2 (1.125)^(1/3) holds a small member of
  // radius 0.5, i.e. R = d · 0.25 / (1.125)^(1/3), half the equal pair's per-sphere share.
  Scene uneven = Glass(0.002);
  uneven.species[0].clump_shape = {{{0, 0, 0}, 1.0}, {{1.5, 0, 0}, 0.5}};
  CHECK(RayleighTime(uneven) ==
        Approx(RayleighTime(Glass(0.002)) * 0.5 / std::cbrt(1.125)).epsilon(1e-9));
  // A placed clump of that species takes its own diameter the same way.
  Scene placed = Glass(0.004);
  placed.species[0].clump_shape = pair.species[0].clump_shape;
  placed.particles.push_back({});
  placed.particles.back().species = 0;
  placed.particles.back().diameter_m = 0.002;
  CHECK(RayleighTime(placed) == Approx(RayleighTime(pair)).epsilon(1e-9));
}

TEST_CASE("Rayleigh time of a clump whose members coincide: shortened by the springs at one point",
          "[core][timestep]") {
  // Three equal members on one centre: the union is one sphere of the grain's diameter, three
  // springs act at each contact point (nine between two such grains) on that sphere's mass, so
  // the step is a third of the sphere's (core/bodies/contact_multiplicity.h).
  Scene stacked = Glass(0.002);
  stacked.species[0].clump_shape = {{{0, 0, 0}, 0.5}, {{0, 0, 0}, 0.5}, {{0, 0, 0}, 0.5}};
  CHECK(RayleighTime(stacked) == Approx(RayleighTime(Glass(0.002)) / 3).epsilon(1e-9));
  CHECK(TimeStep(stacked) == Approx(0.2 * RayleighTime(Glass(0.002)) / 3).epsilon(1e-9));
}
