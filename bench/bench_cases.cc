#include "bench/bench_cases.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "core/bodies/clump_template.h"
#include "core/math/random.h"
#include "core/walls/walls.h"

namespace demcal::bench {
namespace {

using core::Vec3;

constexpr double kDiameter = 0.002, kDensity = 2500, kYoungs = 5e6, kPoisson = 0.25;
constexpr double kGravity = 9.81;
// The pour column's loose pack: about the reference bed's (20,000 spheres of 2 mm fill 14.5 % of
// its 60 × 60 × 160 mm box, 15.8 % of the fill region 1 mm clear of the walls).
constexpr double kLooseSolidFraction = 0.147;

// N spheres of the bench diameter in a row along x, centres one radius apart.
std::vector<core::ShapeSphere> RodClump(int n) {
  std::vector<core::ShapeSphere> rod;
  const double r = 0.5 * kDiameter;
  for (int k = 0; k < n; ++k) rod.push_back({{(k - 0.5 * (n - 1)) * r, 0, 0}, r});
  return rod;
}

// Equivalent-volume diameter of a clump shape as given (in metres).
double EquivalentDiameter(const std::vector<core::ShapeSphere>& shape) {
  std::vector<core::ClumpSphere> spheres;
  for (const core::ShapeSphere& s : shape) spheres.push_back({s.centre, s.radius});
  core::ClumpTemplate t;
  std::string error;
  if (!core::BuildClumpTemplate(spheres, kDensity, {}, &t, &error)) throw std::runtime_error(error);
  return t.EquivalentVolumeDiameter();
}

// Γ (J/m²) for a cohesion number between two bench spheres: R* = r/2, E* = E / (2(1 − ν²)).
double GammaForCohesion(double coh) {
  const double r_eff = 0.25 * kDiameter, e_eff = kYoungs / (2 * (1 - kPoisson * kPoisson));
  return std::pow(std::pow(coh * kDensity * kGravity, 3) * e_eff * e_eff * std::pow(r_eff, 8), 0.2);
}

core::PairParameters BenchPair() {
  core::PairParameters pair;
  pair.sliding_friction = 0.5;
  pair.rolling_friction = 0.1;
  pair.restitution = 0.5;
  return pair;
}

}  // namespace

BedBox DenseBedBox(const BedOptions& o) {
  BedBox box;
  if (o.clump_spheres > 0) {
    box.height_m = 0.3;  // a loose pour of rods needs more room than one of spheres
    box.margin_m = 0.5 * (o.clump_spheres + 1) * 0.5 * kDiameter;
  }
  if (o.particles > kReferenceBedSpheres) {
    // The footprint grows with the count at the reference's height, so the loose pack keeps
    // its solid fraction; whole millimetres keep the LIGGGHTS inputs readable.
    const double side =
        kReferenceBedSide_m * std::sqrt(static_cast<double>(o.particles) / kReferenceBedSpheres);
    box.side_m = std::ceil(side * 1000) / 1000;
  }
  return box;
}

core::Scene DenseBedScene(const BedOptions& c) {
  core::Scene s;
  s.materials = {{"glass", kYoungs, kPoisson, kDensity}};
  s.species = {{"sphere", 0, {}, {}}};
  s.species[0].size.diameter_m = kDiameter;
  int64_t count = c.particles;
  const BedBox box = DenseBedBox(c);
  if (c.clump_spheres > 0) {
    s.species[0].clump_shape = RodClump(c.clump_spheres);
    s.species[0].size.diameter_m = EquivalentDiameter(s.species[0].clump_shape);
    count = std::llround(static_cast<double>(c.particles) / c.clump_spheres);
  }
  core::PairParameters pair = BenchPair();
  pair.interfacial_energy_J_m2 = c.cohesion > 0 ? GammaForCohesion(c.cohesion) : 0;
  s.pair_parameters = {pair};
  s.rolling.name = "epsd2";
  const double side = box.side_m, height = box.height_m, margin = box.margin_m;
  s.walls = core::BoxInnerFaces("box", {0, 0, 0}, {side, side, height}, 0, /*open_top=*/true);
  s.domain_min_m = {0, 0, 0};
  s.domain_max_m = {side, side, height + 0.04};
  s.fills.push_back({0, {margin, margin, margin}, {side - margin, side - margin, height - margin},
                     count, {0, 0, -0.5}});
  s.seed = c.seed;
  s.time.timestep_s = 2.4e-5;
  s.skin_m = 0.0005;
  return s;
}

PourColumn PourFillColumn(int64_t spheres, double mean_volume_m3, double min_base_radius_m) {
  PourColumn c;
  // π R² (4R) φ = N v̄
  const double volume = static_cast<double>(spheres) * mean_volume_m3 / kLooseSolidFraction;
  c.radius_m = std::cbrt(volume / (4 * std::numbers::pi));
  c.z_lo_m = 2 * kDiameter;  // clear of the base spheres (tops at most 1.5 d)
  c.z_hi_m = c.z_lo_m + 4 * c.radius_m;
  c.base_radius_m = std::max(min_base_radius_m, 2 * c.radius_m);
  return c;
}

core::Scene PourScene(const PourOptions& o) {
  core::Scene s;
  s.materials = {{"glass", kYoungs, kPoisson, kDensity}};
  s.species = {{"sphere", 0, {}, {}}};
  s.species[0].size = {core::SizeDistribution::Kind::kUniform, 0, 0.0018, 0.0022, {}, {}};
  s.pair_parameters = {BenchPair()};
  s.rolling.name = "epsd2";
  const PourColumn column = PourFillColumn(o.particles, s.species[0].size.MeanVolume(),
                                           o.base_radius_m);
  const double base_radius = o.particles > 0 ? column.base_radius_m : o.base_radius_m;
  const double half = base_radius + 0.01;
  const double top = (o.particles > 0 ? column.z_hi_m : o.stream_height_m) + 0.02;
  s.walls = core::BoxInnerFaces("box", {-half, -half, 0}, {half, half, top}, 0, true);
  s.domain_min_m = {-half, -half, 0};
  s.domain_max_m = {half, half, top + 0.02};
  // The frozen base: a square grid clipped to the disc, each sphere lifted at random.
  core::Rng rng(core::DeriveSeed(o.seed, 77));
  const double d = kDiameter, r = 0.5 * d;
  const int n = static_cast<int>(std::floor(2 * base_radius / d));
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const Vec3 at{(i - 0.5 * (n - 1)) * d, (j - 0.5 * (n - 1)) * d,
                    r * (1 + 0.5 * rng.Uniform())};
      if (at.x * at.x + at.y * at.y > base_radius * base_radius) continue;
      core::ParticleSpec p{0, at, {}, {}, d, {}};
      p.fixed = true;
      s.particles.push_back(p);
    }
  const Vec3 down{0, 0, -1.5};  // fast enough for the stream's rate in a 5 mm stream
  if (o.particles > 0) {
    s.fills.push_back({0, core::InsertionRegion::Cylinder({0, 0, 0}, column.radius_m,
                                                          column.z_lo_m, column.z_hi_m),
                       o.particles, down});
  } else {
    core::FactorySpec stream;
    stream.name = "stream";
    stream.region = core::InsertionRegion::Cylinder({0, 0, 0}, 0.005, o.stream_height_m - 0.02,
                                                    o.stream_height_m);
    stream.species = {0};
    stream.mass_fractions = {1};
    stream.mass_rate_kg_s = o.mass_rate_kg_s;
    stream.velocity_m_s = down;
    s.factories = {stream};
  }
  s.seed = o.seed;
  s.time.timestep_s = 2.4e-5;
  s.skin_m = 0.0005;
  return s;
}

}  // namespace demcal::bench
