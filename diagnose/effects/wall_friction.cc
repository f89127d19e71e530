// Particle–wall friction: the sliding friction between the subject species' material and every
// wall material (those no species is made of) shifted by Δμw. A wrong wall friction moves what
// the walls hold — a narrow heap's flanks, a hopper's flow — and little else. Probe Δμw = +0.3;
// it may also fall (down to μw = 0 on the smoothest wall) when the walls were given too rough.
#include "diagnose/effects/effect_registry.h"
#include "diagnose/effects/effect_support.h"

namespace demcal::diagnose {
namespace {

class WallFriction final : public Effect {
 public:
  std::string Key() const override { return "wall_friction"; }
  std::string Description() const override {
    return "particle-wall friction: sliding friction between the species and every wall material "
           "shifted by delta_mu_w";
  }
  std::vector<EffectParameter> Parameters(const EffectContext& c) const override {
    // Down to μw = 0 on the smoothest wall.
    return {{"delta_mu_w", "", -c.wall_friction, 0.6, 0.3, "higher wall friction than assumed",
             c.wall_friction > 0 ? "lower wall friction than assumed" : "", c.wall_friction}};
  }
  bool Apply(const std::vector<double>& v, const calibrate::Condition&, const EffectContext& c,
             core::Scene* model, std::string* why) const override {
    int m = 0;
    if (!FindMaterial(*model, c.material, &m, why)) return false;
    if (c.wall_materials.empty()) return *why = "the model has no wall material", false;
    for (const std::string& wall : c.wall_materials) {
      int w = 0;
      if (!FindMaterial(*model, wall, &w, why)) return false;
      if (!ShiftPairProperty(calibrate::PairProperty::kSlidingFriction, m, w, v[0], model, why))
        return false;
    }
    return true;
  }
};

}  // namespace

const Effect* WallFrictionEffect() {
  static const WallFriction effect;
  return &effect;
}

}  // namespace demcal::diagnose
