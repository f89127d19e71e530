// sjkr cohesion: the subject species' self-contact gets LIGGGHTS' `cohesion sjkr` energy density
// k (J/m³; core/contact/sjkr.h: an attraction k·A while the grains overlap, A the area of their
// surfaces' intersection circle). The other adhesion law a user's data may come from: EDEM's JKR
// (jkr_adhesion) pulls with a neck and a pull-off distance, LIGGGHTS' sjkr only while pressed, so
// the two raise a heap differently with the same coating. As jkr_adhesion, k follows the
// coating level when the measurements have a coating column, k = q · w (q in J/m³ per unit of the
// column, zero for uncoated material), else k = q everywhere; added to any k the model has, and
// may take it away (down to k = 0).
// Probe, by the rule the LIGGGHTS export already maps JKR with (docs/export.md): the k that
// spreads JKR's pull-off force F_c = 3πΓR* over JKR's zero-load contact area π a0²
// (a0³ = 9πΓR*²/E*), at jkr_adhesion's probe Γ and the species' own E* and R* (full scale, as
// every effect acts before the fidelity). Upper bound 3 × the probe: the same ratio as
// jkr_adhesion's bound to its probe, because both laws' forces scale linearly in their
// parameter (F_c ∝ Γ, k·A ∝ k), so the strongest force tried is as many times the probe's in both.
#include "calibrate/liggghts_export.h"
#include "diagnose/effects/effect_registry.h"
#include "diagnose/effects/effect_support.h"

namespace demcal::diagnose {
namespace {

// Bound over probe, as jkr_adhesion's (see the top).
constexpr double kUpperOverProbe = kJkrUpperGamma_J_m2 / kJkrProbeGamma_J_m2;

class SjkrCohesion final : public Effect {
 public:
  std::string Key() const override { return "sjkr_cohesion"; }
  std::string Mechanism() const override { return "adhesion"; }
  std::string Description() const override {
    return "sjkr cohesion (LIGGGHTS): cohesion energy density of the species' self-contact, an "
           "attraction over the overlap's area, proportional to the coating level when the data "
           "have a coating column";
  }
  std::vector<EffectParameter> Parameters(const EffectContext& c) const override {
    const double scale = CoatingScale(c);
    const double probe = calibrate::SjkrEnergyDensity(
        kJkrProbeGamma_J_m2, c.self_effective_youngs_Pa, c.self_effective_radius_m);
    // Down to k = 0 at the largest coating level (k_base + q·w ≥ 0 for every w up to it).
    return {{CoatingScaledName(c, "k_J_m3", "k", "J_m3"), "J/m3",
             -c.cohesion_energy_density / scale, kUpperOverProbe * probe / scale, probe / scale,
             "more cohesion than assumed",
             c.cohesion_energy_density > 0 ? "less cohesion than assumed" : "",
             c.cohesion_energy_density / scale}};
  }
  bool Apply(const std::vector<double>& v, const calibrate::Condition& condition,
             const EffectContext& c, core::Scene* model, std::string* why) const override {
    return ShiftSelfContactWithCoating(calibrate::PairProperty::kCohesionEnergyDensity, v[0],
                                       condition, c, model, why);
  }
};

}  // namespace

const Effect* SjkrCohesionEffect() {
  static const SjkrCohesion effect;
  return &effect;
}

}  // namespace demcal::diagnose
