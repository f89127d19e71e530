#pragma once
// The scene the checkpoint tests and the checkpoint fuzzer (fuzz/fuzz_checkpoint.cc) restart:
// spheres and 2-sphere clumps poured by a factory into an open-top box of planes, with EPSD
// rolling springs and JKR adhesion (hysteresis), so a checkpoint of it holds every kind of
// particle, clump, contact-history and factory state. Each user sizes the box, the feed and the
// adhesion for its purpose and adds what it needs on top (walls of other shapes, friction).
// Header-only and free of Catch2: the fuzzer includes it too.
#include <cstdint>

#include "core/insertion/insertion_region.h"
#include "core/math/vec3.h"
#include "core/scene/scene.h"
#include "core/walls/walls.h"

namespace demcal::core::checkpoint_test {

struct PourSpec {
  Vec3 box_max_m;                  // the box spans the origin to here; so does the domain
  double interfacial_energy_J_m2;  // Γ of every pair (JKR)
  double feed_radius_m;            // the feed is a vertical cylinder on the box's centre line
  double feed_z_lo_m, feed_z_hi_m;
  double feed_rate_kg_s;
  uint64_t seed;
};

// Material "m" (E = 5 MPa, ν = 0.25, 1500 kg/m³); species "balls" (uniform 1.8–2.2 mm) and
// "pairs" (two overlapping 0.6 d spheres, d = 2.5 mm), fed half and half by mass; μ_r = 0.1.
inline Scene PourScene(const PourSpec& spec) {
  Scene s;
  s.materials = {{"m", 5e6, 0.25, 1500}};
  s.species = {{"balls", 0, {}, {}}, {"pairs", 0, {}, {{{-0.5, 0, 0}, 0.6}, {{0.5, 0, 0}, 0.6}}}};
  s.species[0].size = {SizeDistribution::Kind::kUniform, 0, 0.0018, 0.0022, {}, {}};
  s.species[1].size.diameter_m = 0.0025;
  PairParameters pair;
  pair.rolling_friction = 0.1;
  pair.interfacial_energy_J_m2 = spec.interfacial_energy_J_m2;
  s.pair_parameters = {pair};
  s.rolling.name = "epsd";
  s.walls = BoxInnerFaces("box", {0, 0, 0}, spec.box_max_m, 0, /*open_top=*/true);
  s.domain_min_m = {0, 0, 0};
  s.domain_max_m = spec.box_max_m;
  FactorySpec f;
  f.name = "feed";
  f.region = InsertionRegion::Cylinder({spec.box_max_m.x / 2, spec.box_max_m.y / 2, 0},
                                       spec.feed_radius_m, spec.feed_z_lo_m, spec.feed_z_hi_m);
  f.species = {0, 1};
  f.mass_fractions = {0.5, 0.5};
  f.mass_rate_kg_s = spec.feed_rate_kg_s;
  s.factories = {f};
  s.seed = spec.seed;
  return s;
}

}  // namespace demcal::core::checkpoint_test
