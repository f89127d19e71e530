#include "objectives/common/feed.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "core/bodies/clump_size.h"
#include "core/bodies/unit_clump.h"

namespace demcal::objectives {

bool Feed::IsValid(const core::Scene& model, const std::string& path, std::string* error) const {
  std::ostringstream os;
  double sum = 0;
  for (size_t k = 0; k < components.size(); ++k) {
    const FeedComponent& c = components[k];
    if (c.species < 0 || c.species >= static_cast<int>(model.species.size()))
      os << path << ".components[" << k << "].species names no defined species";
    else if (!(c.mass_fraction > 0 && c.mass_fraction <= 1))
      os << path << ".components[" << k << "].mass_fraction = " << c.mass_fraction
         << " is outside the allowed range (0, 1]";
    if (!os.str().empty()) break;
    sum += c.mass_fraction;
  }
  if (os.str().empty()) {
    if (components.empty())
      os << path << ".components is empty: name at least one species";
    else if (std::abs(sum - 1) > 1e-6)
      os << path << ".components: mass fractions sum to " << sum << ", they must sum to 1";
    else if (!(mass_kg > 0 && std::isfinite(mass_kg)))
      os << path << ".mass_kg = " << mass_kg << " is outside the allowed range (0, inf)";
    else if (!(mass_rate_kg_s > 0 && std::isfinite(mass_rate_kg_s)))
      os << path << ".mass_rate_kg_s = " << mass_rate_kg_s << " is outside the allowed range (0, inf)";
  }
  if (os.str().empty()) return true;
  if (error) *error = os.str();
  return false;
}

double FeedEntrySpeed(const core::Scene& model, const Feed& feed,
                      const core::InsertionRegion& region, double solid_fraction, double g_m_s2) {
  double volume_per_kg = 0;  // of solid, m³/kg, over the feed's mass fractions
  for (const FeedComponent& c : feed.components)
    volume_per_kg +=
        c.mass_fraction / model.materials[model.species[c.species].material].density_kg_m3;
  const double h = region.max_m.z - region.min_m.z;
  // Longest batch interval T allowed: rate · T · volume_per_kg <= fraction · region volume.
  const double t_max = solid_fraction * region.Volume() / (feed.mass_rate_kg_s * volume_per_kg);
  if (std::sqrt(2 * h / g_m_s2) <= t_max) return 0;
  // Fall-through time (−v + √(v² + 2gh))/g = T  ⇔  v = h/T − gT/2.
  return h / t_max - 0.5 * g_m_s2 * t_max;
}

bool FeedInserted(const core::Simulation& sim, const Feed& feed) {
  const core::FactoryReport* r = sim.FindFactoryReport("feed");
  return !r || r->inserted_mass_kg >= feed.mass_kg;
}

double FeedTookS(const Feed& feed, double inserted_at_s, double check_interval_s) {
  if (inserted_at_s < 0 || inserted_at_s <= feed.EndS() + check_interval_s)
    return feed.DurationS();
  return inserted_at_s - feed.start_s;
}

core::FactorySpec MakeFeedFactory(const core::Scene& model, const Feed& feed,
                                  const core::InsertionRegion& region) {
  core::FactorySpec spec;
  spec.name = "feed";
  spec.region = region;
  for (const FeedComponent& c : feed.components) {
    spec.species.push_back(c.species);
    spec.mass_fractions.push_back(c.mass_fraction);
  }
  spec.mass_rate_kg_s = feed.mass_rate_kg_s;
  spec.start_s = feed.start_s;
  spec.total_mass_kg = feed.mass_kg;
  spec.velocity_m_s = feed.velocity_m_s;
  if (feed.velocity_m_s.x == 0 && feed.velocity_m_s.y == 0 && feed.velocity_m_s.z == 0) {
    const double g = std::sqrt(Dot(model.gravity_m_s2, model.gravity_m_s2));
    spec.velocity_m_s.z = -FeedEntrySpeed(model, feed, region, 0.2, g);
  }
  return spec;
}

double FeedMaxDiameter(const core::Scene& model, const Feed& feed) {
  double d = 0;
  for (const FeedComponent& c : feed.components)
    d = std::max(d, model.species[c.species].size.MaxDiameter());
  return d;
}

namespace {

// The species' grain at unit equivalent-volume diameter; false for a sphere. A shape that
// makes no clump was refused when the scene was read (ParticleSystem::SetSpecies).
bool UnitShape(const core::Species& species, core::ClumpTemplate* shape) {
  std::string unused;
  return !species.clump_shape.empty() &&
         core::UnitDiameterClumpTemplate(species.clump_shape, shape, &unused);
}

// Largest over the feed's species of size(unit shape) × the species' largest diameter, where a
// sphere's size at unit diameter is 1.
template <typename UnitSize>
double FeedMaxSize(const core::Scene& model, const Feed& feed, UnitSize unit_size) {
  double d = 0;
  for (const FeedComponent& c : feed.components) {
    const core::Species& species = model.species[c.species];
    core::ClumpTemplate shape;
    const double unit = UnitShape(species, &shape) ? unit_size(shape) : 1.0;
    d = std::max(d, unit * species.size.MaxDiameter());
  }
  return d;
}

}  // namespace

double FeedMaxEnclosingDiameter(const core::Scene& model, const Feed& feed) {
  return FeedMaxSize(model, feed,
                     [](const core::ClumpTemplate& t) { return 2 * t.BoundingRadius(); });
}

double FeedMaxMeanCaliperDiameter(const core::Scene& model, const Feed& feed) {
  return FeedMaxSize(model, feed,
                     [](const core::ClumpTemplate& t) { return core::MeanCaliperDiameter(t.spheres); });
}

double FeedMinDiameter(const core::Scene& model, const Feed& feed) {
  double d = std::numeric_limits<double>::infinity();
  for (const FeedComponent& c : feed.components)
    d = std::min(d, model.species[c.species].size.MinDiameter());
  return d;
}

}  // namespace demcal::objectives
