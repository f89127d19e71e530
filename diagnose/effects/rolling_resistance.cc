// Rolling resistance: the subject species' self-contact rolling friction μr changes by Δμr (either
// sign, μr ≥ 0) (the model's own rolling model, CDT or EPSD: core/contact/rolling_model.h). Stands
// for every mechanism that resists rolling without changing the contact's sliding: surface
// asperities, angularity below the clump scale. Probe Δμr = 0.2.
#include "diagnose/effects/effect_registry.h"
#include "diagnose/effects/effect_support.h"

namespace demcal::diagnose {
namespace {

class RollingResistance final : public Effect {
 public:
  std::string Key() const override { return "rolling_resistance"; }
  std::string Description() const override {
    return "rolling resistance: rolling friction of the species' self-contact shifted by "
           "delta_mu_r";
  }
  std::vector<EffectParameter> Parameters(const EffectContext& c) const override {
    // Down to μr = 0 at the base's value (no negative rolling friction).
    return {{"delta_mu_r", "", -c.rolling_friction, 1.0, 0.2,
             "more rolling resistance than assumed",
             c.rolling_friction > 0 ? "less rolling resistance than assumed" : "",
             c.rolling_friction}};
  }
  bool Apply(const std::vector<double>& v, const calibrate::Condition&, const EffectContext& c,
             core::Scene* model, std::string* why) const override {
    int m = 0;
    if (!FindMaterial(*model, c.material, &m, why)) return false;
    return ShiftPairProperty(calibrate::PairProperty::kRollingFriction, m, m, v[0], model, why);
  }
};

}  // namespace

const Effect* RollingResistanceEffect() {
  static const RollingResistance effect;
  return &effect;
}

}  // namespace demcal::diagnose
