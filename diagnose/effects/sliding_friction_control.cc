// Control: a miscalibrated sliding friction. The species' self-contact sliding friction μs
// shifted by Δμs. When the study already fits μs its signature lies in the span of the base
// model's own sensitivities, so the refit gains nothing and the ranking must not name it: a
// check that the ranking rewards new physics, not a second copy of a fitted parameter. When
// the study does not fit μs, it is a genuine candidate (a wrong fixed μs). Probe +0.2.
#include <algorithm>

#include "diagnose/effects/effect_registry.h"
#include "diagnose/effects/effect_support.h"

namespace demcal::diagnose {
namespace {

class SlidingFrictionControl final : public Effect {
 public:
  std::string Key() const override { return "sliding_friction_control"; }
  std::string Description() const override {
    return "control: sliding friction of the species' self-contact shifted by delta_mu_s "
           "(redundant when the study "
           "fits it)";
  }
  std::vector<EffectParameter> Parameters(const EffectContext& c) const override {
    return {{"delta_mu_s", "", -std::min(0.5, c.sliding_friction), 0.8, 0.2,
             "more sliding friction than assumed",
             c.sliding_friction > 0 ? "less sliding friction than assumed" : ""}};
  }
  bool Apply(const std::vector<double>& v, const calibrate::Condition&, const EffectContext& c,
             core::Scene* model, std::string* why) const override {
    int m = 0;
    if (!FindMaterial(*model, c.material, &m, why)) return false;
    return ShiftPairProperty(calibrate::PairProperty::kSlidingFriction, m, m, v[0], model, why);
  }
};

}  // namespace

const Effect* SlidingFrictionControlEffect() {
  static const SlidingFrictionControl effect;
  return &effect;
}

}  // namespace demcal::diagnose
