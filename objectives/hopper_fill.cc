#include "objectives/hopper_fill.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace demcal::objectives {

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kPlacedSolidFraction = 0.2;
constexpr double kBulkSolidFraction = 0.6;

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

}  // namespace

core::InsertionRegion FeedRegion(const core::Scene& model, const DischargeSettings& s) {
  const double d = FeedMaxDiameter(model, s.feed);
  const double z0 = s.hopper.TopM() + d;
  if (s.fill == DischargeSettings::Fill::kPour) {
    const double diameter =
        s.feed_diameter_m > 0 ? s.feed_diameter_m : 0.6 * s.hopper.top_diameter_m;
    return core::InsertionRegion::Cylinder({0, 0, 0}, 0.5 * diameter, z0,
                                           z0 + std::max(6 * d, 0.01));
  }
  const double a = 0.5 * s.hopper.top_diameter_m / std::numbers::sqrt2 - d;
  const double height = SolidVolume(model, s.feed) / kPlacedSolidFraction / (4 * a * a);
  return core::InsertionRegion::Box({-a, -a, z0}, {a, a, z0 + std::max(height, 2 * d)});
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
  const double bulk = SolidVolume(model, s.feed) / kBulkSolidFraction;
  const double width = 1.5 * s.hopper.top_diameter_m;  // the catch bin's side
  const double room = width * width * s.catch_depth_m;
  if (bulk <= 0.4 * room) return true;
  *os << "discharge.catch_depth_m = " << s.catch_depth_m << " leaves a catch bin of " << room
      << " m3 under the orifice, too small for the heap of the discharged feed (about " << bulk
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
  double mass = 0;
  for (size_t i = 0; i < p.Size(); ++i) {
    const core::Vec3& x = p.position_m[i];
    if (x.z < z_lo || x.z > z_hi) continue;
    if (std::hypot(x.x, x.y) <= HopperRadius(h, x.z) - d_m) mass += p.mass_kg[i];
  }
  return volume > 0 ? mass / volume : 0;
}

}  // namespace demcal::objectives
