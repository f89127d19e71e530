#include "objectives/common/glued_base.h"

#include <cmath>

#include "core/math/random.h"
#include "core/math/seed_streams.h"

namespace demcal::objectives {

GluedBaseSpec GluedBaseOfFeed(const core::Scene& model, const Feed& feed, uint64_t seed) {
  GluedBaseSpec base;
  base.species = feed.components.front().species;
  const core::SizeDistribution& size = model.species[base.species].size;
  base.diameter_m = 0.5 * (size.MinDiameter() + size.MaxDiameter());
  base.seed = core::DeriveSeed(seed, core::kGluedBaseStream);
  return base;
}

void UseSphereSpeciesForBase(core::Scene* scene, GluedBaseSpec* spec) {
  const core::Species& feed = scene->species[spec->species];
  if (feed.clump_shape.empty()) return;
  core::Species base;
  base.name = feed.name + " glued base";
  base.material = feed.material;
  base.size.diameter_m = spec->diameter_m;
  scene->species.push_back(base);
  spec->species = static_cast<int>(scene->species.size()) - 1;
}

std::vector<core::ParticleSpec> GluedBase(const GluedBaseSpec& spec) {
  const double d = spec.diameter_m, r = 0.5 * d;
  const core::Vec3 centre = 0.5 * (spec.min_m + spec.max_m);
  const int nx = static_cast<int>(std::floor((spec.max_m.x - spec.min_m.x) / d));
  const int ny = static_cast<int>(std::floor((spec.max_m.y - spec.min_m.y) / d));
  const double x0 = centre.x - 0.5 * (nx - 1) * d, y0 = centre.y - 0.5 * (ny - 1) * d;
  core::Rng rng(spec.seed);
  std::vector<core::ParticleSpec> layer;
  for (int i = 0; i < nx; ++i) {
    for (int j = 0; j < ny; ++j) {
      core::ParticleSpec p;
      p.species = spec.species;
      p.diameter_m = d;
      p.fixed = true;
      // Lifted by up to half a radius: neighbours at pitch d never overlap more than that.
      p.position_m = {x0 + i * d, y0 + j * d, spec.min_m.z + r * (1 + 0.5 * rng.Uniform())};
      const double dx = p.position_m.x - centre.x, dy = p.position_m.y - centre.y;
      if (spec.disc_radius_m > 0 && dx * dx + dy * dy > spec.disc_radius_m * spec.disc_radius_m)
        continue;
      layer.push_back(p);
    }
  }
  return layer;
}

}  // namespace demcal::objectives
