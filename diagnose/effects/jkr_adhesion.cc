// JKR adhesion: the subject species' self-contact gets an interfacial energy Γ (J/m², EDEM
// convention, work of adhesion 2Γ; core/contact/jkr.h). Adhesion comes from a binder or a
// coating, so when the measurements have a coating column its Γ follows the coating level,
// Γ = g · w (g in J/m² per unit of the column, zero for uncoated material: the paper's Γ(w),
// Alizadeh et al. 2018 section 2.5.3); without one Γ = g everywhere. Added to any Γ the model
// has, and may take it away (down to Γ = 0) when the base assumes adhesion. Probe: Γ = 0.01 J/m² at
// the largest coating level, bounds up to 0.03 J/m² there: a few times below the paper's 0.046 J/m²
// (0.5 wt% PEG on the larger EP), because much stronger adhesion on the small BP grains keeps a
// coarse-grained heap from settling (tried: Γ = 0.05 J/m² at quick fidelity never settled; 0.02
// J/m² doubled the angle).
#include "diagnose/effects/effect_registry.h"
#include "diagnose/effects/effect_support.h"

namespace demcal::diagnose {
namespace {

class JkrAdhesion final : public Effect {
 public:
  std::string Key() const override { return "jkr_adhesion"; }
  std::string Mechanism() const override { return "adhesion"; }
  std::string Description() const override {
    return "JKR adhesion: interfacial energy of the species' self-contact, proportional to the "
           "coating level "
           "when the data have a coating column";
  }
  std::vector<EffectParameter> Parameters(const EffectContext& c) const override {
    const double scale = CoatingScale(c);
    // Down to Γ = 0 at the largest coating level (Γ_base + g·w ≥ 0 for every w up to it).
    return {{CoatingScaledName(c, "gamma_J_m2", "gamma", "J_m2"), "J/m2",
             -c.interfacial_energy / scale, kJkrUpperGamma_J_m2 / scale,
             kJkrProbeGamma_J_m2 / scale, "more adhesion than assumed",
             c.interfacial_energy > 0 ? "less adhesion than assumed" : "",
             c.interfacial_energy / scale}};
  }
  bool Apply(const std::vector<double>& v, const calibrate::Condition& condition,
             const EffectContext& c, core::Scene* model, std::string* why) const override {
    return ShiftSelfContactWithCoating(calibrate::PairProperty::kInterfacialEnergy, v[0],
                                       condition, c, model, why);
  }
};

}  // namespace

const Effect* JkrAdhesionEffect() {
  static const JkrAdhesion effect;
  return &effect;
}

}  // namespace demcal::diagnose
