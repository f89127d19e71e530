#include "experiments/discharge/hopper_fill.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "core/math/random.h"
#include "core/math/seed_streams.h"
#include "experiments/discharge/sphere_mass_share.h"

namespace demcal::objectives {

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kBulkSolidFraction = 0.6;
// Placed lattice: spacing and jitter in largest diameters d; wall clearance of a centre.
constexpr double kLatticeSpacing = 1.1, kJitter = 0.04 * kLatticeSpacing, kClearance = 0.55;

double SolidVolume(const core::Scene& model, const Feed& feed) {
  double volume = 0;
  for (const FeedComponent& c : feed.components)
    volume += c.mass_fraction * feed.mass_kg /
              model.materials[model.species[c.species].material].density_kg_m3;
  return volume;
}

// Inner radius of the hopper at height z above the orifice.
double HopperRadius(const HopperGeometry& h, double z_m) {
  const double cone = h.ConeHeightM();
  const double r0 = 0.5 * h.orifice_diameter_m, r1 = 0.5 * h.top_diameter_m;
  return z_m >= cone ? r1 : r0 + (r1 - r0) * z_m / cone;
}

// True when a grain centred at (ρ, z) clears the closed gate (z = 0), the cone and the cylinder
// (or, above the rim, stays inside its footprint) by `clear_m`.
bool InsideHopper(const HopperGeometry& h, double rho_m, double z_m, double clear_m) {
  const double half_angle = h.cone_half_angle_deg * kPi / 180;
  // Distance to the cone's generatrix through the orifice edge, positive inside.
  const double to_cone = z_m * std::sin(half_angle) -
                         (rho_m - 0.5 * h.orifice_diameter_m) * std::cos(half_angle);
  return z_m >= clear_m && to_cone >= clear_m && rho_m <= 0.5 * h.top_diameter_m - clear_m;
}

// Lattice sites of a placed fill, bottom layer first, until `count` are found.
std::vector<core::Vec3> LatticeSites(const HopperGeometry& h, double d_m, int64_t count) {
  const double a = kLatticeSpacing * d_m, clear = kClearance * d_m;
  const int half_n = static_cast<int>(std::ceil(0.5 * h.top_diameter_m / a));
  std::vector<core::Vec3> sites;
  for (double z = clear; static_cast<int64_t>(sites.size()) < count; z += a)
    for (int i = -half_n; i <= half_n; ++i)
      for (int j = -half_n; j <= half_n; ++j)
        if (static_cast<int64_t>(sites.size()) < count &&
            InsideHopper(h, std::hypot(i * a, j * a), z, clear))
          sites.push_back({i * a, j * a, z});
  return sites;
}

int64_t PlacedTotal(const core::Scene& model, const Feed& feed) {
  int64_t n = 0;
  for (const FeedComponent& c : feed.components) n += PlacedCount(model, feed, c);
  return n;
}

}  // namespace

core::InsertionRegion FeedRegion(const core::Scene& model, const DischargeSettings& s) {
  const double d = FeedMaxDiameter(model, s.feed);
  const double z0 = s.hopper.TopM() + d;
  const double diameter =
      s.feed_diameter_m > 0 ? s.feed_diameter_m : 0.6 * s.hopper.top_diameter_m;
  return core::InsertionRegion::Cylinder({0, 0, 0}, 0.5 * diameter, z0,
                                         z0 + std::max(6 * d, 0.01));
}

std::vector<core::ParticleSpec> PlacedFill(const core::Scene& model, const DischargeSettings& s,
                                           uint64_t seed) {
  const double d = FeedMaxDiameter(model, s.feed);
  std::vector<int> species;
  for (const FeedComponent& c : s.feed.components)
    species.insert(species.end(), PlacedCount(model, s.feed, c), c.species);
  core::Rng rng(core::DeriveSeed(seed, core::kHopperPlacementStream));
  for (size_t i = species.size(); i > 1; --i)  // Fisher–Yates
    std::swap(species[i - 1], species[static_cast<size_t>(rng.Uniform() * i)]);
  const std::vector<core::Vec3> sites =
      LatticeSites(s.hopper, d, static_cast<int64_t>(species.size()));
  std::vector<core::ParticleSpec> grains;
  for (size_t k = 0; k < sites.size(); ++k) {
    const core::Vec3 jitter{rng.Uniform(-kJitter, kJitter), rng.Uniform(-kJitter, kJitter),
                            rng.Uniform(-kJitter, kJitter)};
    grains.push_back({.species = species[k], .position_m = sites[k] + jitter * d});
  }
  return grains;
}

double FillTopM(const core::Scene& model, const DischargeSettings& s) {
  if (s.fill == DischargeSettings::Fill::kPour) return FeedRegion(model, s).max_m.z;
  const double d = FeedMaxDiameter(model, s.feed);
  const std::vector<core::Vec3> sites = LatticeSites(s.hopper, d, PlacedTotal(model, s.feed));
  return (sites.empty() ? 0.0 : sites.back().z) + d;
}

int64_t PlacedCount(const core::Scene& model, const Feed& feed, const FeedComponent& c) {
  const core::Species& species = model.species[c.species];
  const double grain_kg =
      model.materials[species.material].density_kg_m3 * species.size.MeanVolume();
  return std::max<int64_t>(1, std::llround(c.mass_fraction * feed.mass_kg / grain_kg));
}

double HopperVolume(const HopperGeometry& h) {
  const double r0 = 0.5 * h.orifice_diameter_m, r1 = 0.5 * h.top_diameter_m;
  return kPi * h.ConeHeightM() / 3 * (r0 * r0 + r0 * r1 + r1 * r1) +
         kPi * r1 * r1 * h.cylinder_height_m;
}

bool FitsInHopper(const core::Scene& model, const DischargeSettings& s, std::ostream* os) {
  const double bulk = SolidVolume(model, s.feed) / kBulkSolidFraction;
  if (bulk <= 0.9 * HopperVolume(s.hopper)) return true;
  *os << "discharge.feed.mass_kg = " << s.feed.mass_kg << " needs about " << bulk
      << " m3 of hopper (at a solid fraction of 0.6) but the hopper holds "
      << HopperVolume(s.hopper)
      << " m3 (90% usable): enlarge top_diameter_m or cylinder_height_m, or reduce the mass";
  return false;
}

bool FitsInCatchBin(const core::Scene& model, const DischargeSettings& s, std::ostream* os) {
  // Only discharge_fraction of the fill leaves before the run stops.
  const double bulk =
      s.analysis.discharge_fraction * SolidVolume(model, s.feed) / kBulkSolidFraction;
  const double width = 1.5 * s.hopper.top_diameter_m;  // the catch bin's side
  const double room = width * width * s.catch_depth_m;
  if (bulk <= 0.4 * room) return true;
  *os << "discharge.catch_depth_m = " << s.catch_depth_m << " leaves a catch bin of " << room
      << " m3 under the orifice, too small for the heap of the discharged feed (discharge_fraction "
      << "of it, about " << bulk
      << " m3, at most 40% of the bin): increase catch_depth_m to at least "
      << bulk / (0.4 * width * width) << " m";
  return false;
}

double HopperBulkDensity(const core::Particles& p, const HopperGeometry& h, double d_m) {
  std::vector<double> heights;
  for (size_t i = 0; i < p.Size(); ++i)
    if (p.position_m[i].z > 0) heights.push_back(p.position_m[i].z);
  if (heights.empty()) return 0;
  std::nth_element(heights.begin(), heights.begin() + heights.size() / 2, heights.end());
  const double z_lo = 2 * d_m, z_hi = std::min(heights[heights.size() / 2], h.TopM());
  if (!(z_hi > z_lo)) return 0;
  // The probe's volume by slices: πr² with r = hopper radius − d, clipped at 0.
  constexpr int kSlices = 200;
  double volume = 0;
  for (int k = 0; k < kSlices; ++k) {
    const double z = z_lo + (k + 0.5) * (z_hi - z_lo) / kSlices;
    const double r = std::max(0.0, HopperRadius(h, z) - d_m);
    volume += kPi * r * r * (z_hi - z_lo) / kSlices;
  }
  const std::vector<double> share = SphereMassShares(p);  // a clump counts once, not per member
  double mass = 0;
  for (size_t i = 0; i < p.Size(); ++i) {
    const core::Vec3& x = p.position_m[i];
    if (x.z < z_lo || x.z > z_hi) continue;
    if (std::hypot(x.x, x.y) <= HopperRadius(h, x.z) - d_m) mass += share[i];
  }
  return volume > 0 ? mass / volume : 0;
}

double FillEndS(const core::Scene& model, const DischargeSettings& s) {
  if (s.fill == DischargeSettings::Fill::kPour) return s.feed.EndS();
  const double g = std::sqrt(Dot(model.gravity_m_s2, model.gravity_m_s2));
  return std::sqrt(2 * FillTopM(model, s) / 3 / g);
}

}  // namespace demcal::objectives
