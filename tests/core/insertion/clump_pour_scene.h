#pragma once
// The clump pour the factory tests share: BP-like grains at the segregation heap's quick
// fidelity, 4-sphere chains of the 3.044 : 1 : 1 ellipsoid, equivalent diameter 2.125–2.5 mm
// uniform, 780 kg/m³, poured at rest from `region` into free fall (no walls, nothing to collide
// with: the region's room alone limits the rate). Header-only and free of Catch2.
#include <limits>
#include <string>

#include "core/bodies/clump_shapes.h"
#include "core/scene/scene.h"

namespace demcal::core::clump_pour {

inline constexpr double kDensity = 780, kDMin = 0.002125, kDMax = 0.0025;

// Empty if the chain shape could not be made (the error then says why).
inline Scene ClumpPour(const InsertionRegion& region, double rate_kg_s,
                       double total_kg = std::numeric_limits<double>::infinity(),
                       std::string* error = nullptr) {
  ShapeApproximation chain;
  std::string why;
  if (!ApproximateEllipsoid({3.044, 1, 1}, 4, &chain, error ? error : &why)) return {};
  Scene s;
  s.materials = {{"bp", 1e6, 0.25, kDensity}};
  s.species = {{"bp", 0, {}, {}}};
  s.species[0].size.kind = SizeDistribution::Kind::kUniform;
  s.species[0].size.min_diameter_m = kDMin;
  s.species[0].size.max_diameter_m = kDMax;
  for (const ClumpSphere& m : chain.spheres)
    s.species[0].clump_shape.push_back({m.centre_m, m.radius_m});
  s.pair_parameters = {PairParameters{}};
  s.gravity_m_s2 = {0, 0, -9.81};
  s.domain_min_m = {-0.02, -0.02, -1.0};
  s.domain_max_m = {0.06, 0.04, 0.04};
  FactorySpec f;
  f.name = "feed";
  f.region = region;
  f.species = {0};
  f.mass_fractions = {1};
  f.mass_rate_kg_s = rate_kg_s;
  f.total_mass_kg = total_kg;
  s.factories = {f};
  s.time.duration_s = 1;
  s.seed = 2018;
  return s;
}

}  // namespace demcal::core::clump_pour
