// Non-spherical shape: the subject species becomes elongated — the equal-volume 3-sphere chain
// of a prolate spheroid with aspect ratio 1 + Δ (semi-axes [1 + Δ, 1, 1],
// core/bodies/clump_shapes.h; the species' diameter stays its equivalent-volume diameter).
// Elongated grains interlock: steeper heaps, looser packing, slower flow. Continuous in Δ (the
// chain's spheres and spacing follow the aspect ratio), so it can be refitted like any parameter. A
// species that is already a clump is left to the study's clump-count loop (docs/calibration.md).
// Probe Δ = 0.8.
#include "core/bodies/clump_shapes.h"
#include "diagnose/effects/effect_registry.h"
#include "diagnose/effects/effect_support.h"

namespace demcal::diagnose {
namespace {

constexpr int kChainSpheres = 3;

class ParticleShape final : public Effect {
 public:
  std::string Key() const override { return "particle_shape"; }
  std::string Description() const override {
    return "non-spherical shape: the species as the equal-volume 3-sphere chain of a spheroid of "
           "aspect ratio "
           "1 + delta_aspect_ratio";
  }
  std::vector<EffectParameter> Parameters(const EffectContext&) const override {
    // One-sided: the base species is a sphere (a clump is refused below), and nothing is rounder.
    return {{"delta_aspect_ratio", "", 0, 2.0, 0.8, "more elongated particles than assumed", ""}};
  }
  bool Apply(const std::vector<double>& v, const calibrate::Condition&, const EffectContext& c,
             core::Scene* model, std::string* why) const override {
    int s = 0;
    if (!FindSpecies(*model, c, &s, why)) return false;
    core::Species& species = model->species[s];
    if (v[0] == 0) return true;
    if (!species.clump_shape.empty())
      return *why = "species '" + species.name + "' is already a clump", false;
    if (!(v[0] > 0)) return *why = "delta_aspect_ratio must be >= 0", false;
    core::ShapeApproximation shape;
    if (!core::ApproximateEllipsoid({1 + v[0], 1, 1}, kChainSpheres, &shape, why)) return false;
    for (const core::ClumpSphere& sphere : shape.spheres)
      species.clump_shape.push_back({sphere.centre_m, sphere.radius_m});
    return true;
  }
};

}  // namespace

const Effect* ParticleShapeEffect() {
  static const ParticleShape effect;
  return &effect;
}

}  // namespace demcal::diagnose
