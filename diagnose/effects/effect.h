#pragma once
// Effect: one candidate physical effect the base model may be missing (JKR adhesion, rolling
// resistance, particle shape, size polydispersity, wall friction, a miscalibrated sliding
// friction as a control). Each declares its extra parameters — all switched off at 0, so the
// base model is the effect at 0 — and how it modifies the full-scale particle model, after the
// study's own parameters were written and before the fidelity is applied (so Γ is the real one
// and is carried at constant Cohesion number like any other). The diagnosis computes each
// effect's signature with the simulator (how every observable in every condition moves when the
// effect is switched on at its probe value, with the same seeds) and refits it
// (diagnose/ranking/). Adding an effect is one file here plus one line in effect_registry.cc.
//
//   const Effect* e = FindEffect("rolling_resistance");
//   EffectContext c = ...;                       // the subject species, walls, covariates
//   e->Apply({0.2}, condition, c, &model, &why); // μr of the species' pair += 0.2
//
// Thread-safety: effects are stateless; Apply writes only into the model it is given.
#include <string>
#include <vector>

#include "calibrate/condition.h"
#include "core/scene/scene.h"

namespace demcal::diagnose {

// Signed: an effect may strengthen what the base model assumes (value > 0) or weaken it
// (value < 0: less rolling resistance, lower wall friction, ...); lower < 0 wherever the
// property can fall without leaving its physical range at the base model's value (μr ≥ 0,
// Γ ≥ 0, k ≥ 0, μw ≥ 0, a relative width ≥ 0).
struct EffectParameter {
  std::string name;  // unique within the effect, unit in the name ("delta_mu_r")
  std::string unit;  // "" for a dimensionless one
  double lower = 0;  // allowed values; 0 (switched off) is inside [lower, upper]
  double upper = 1;
  double probe = 0.5;  // where the signature is computed, != 0
  std::string
      more;  // the direction of a value > 0 in words: "more rolling resistance than assumed"
  std::string less;  // of a value < 0 ("" when the effect cannot fall below the base)
  // The base model's own amount of what the parameter shifts, in the parameter's units (μr of
  // the base for Δμr; 0 when the base model lacks the mechanism: no adhesion, spheres). A
  // change by no more than it re-values a modelled parameter rather than adding a missing
  // mechanism (diagnose/ranking/revaluation.h).
  double assumed = 0;
};

// The direction of a value of p in words: p.more, p.less, or "switched off" at 0.
inline std::string EffectDirection(const EffectParameter& p, double value) {
  return value > 0 ? p.more : value < 0 ? p.less : "switched off";
}

// What an effect acts on, found from the study (diagnose/dem/effect_context.h).
struct EffectContext {
  std::string species;                      // the subject species (of the study's parameters)
  std::string material;                     // its material
  std::vector<std::string> wall_materials;  // materials no species is made of
  std::string coating_column;  // a numeric condition column whose name starts with "coating"
  double coating_max = 0;      // its largest value among the observations (> 0 when set)
  // The base model's values the signed effects shift (the first experiment file's model): the
  // lower bounds keep each property inside its physical range there.
  double sliding_friction = 0;    // species' self-contact μs
  double rolling_friction = 0;    // species' self-contact μr
  double interfacial_energy = 0;  // species' self-contact Γ, J/m²
  double cohesion_energy_density = 0;  // species' self-contact sjkr k, J/m³
  // The species' self-contact E* (Pa) and R* (m, half its mean radius), at full scale: what an
  // adhesion effect converts its probe with.
  double self_effective_youngs_Pa = 0;
  double self_effective_radius_m = 0;
  double wall_friction = 0;       // the smallest μs between the species and a wall material
  double relative_width = 0;      // (d_max − d_min) / d_mean of its size cut
};

class Effect {
 public:
  virtual ~Effect() = default;
  virtual std::string Key() const = 0;          // "jkr_adhesion"
  virtual std::string Description() const = 0;  // what it changes in the model, in words
  // The physical mechanism the effect is one law of ("adhesion" for JKR and sjkr). Two laws of
  // one mechanism that fit equally still name the mechanism (ranking.h); by default an effect is
  // a mechanism of its own.
  virtual std::string Mechanism() const { return Key(); }
  virtual std::vector<EffectParameter> Parameters(const EffectContext& context) const = 0;
  // Writes the effect with these values (one per parameter) into the model of one condition.
  // False with why when the model lacks what the effect acts on or the value is out of range.
  virtual bool Apply(const std::vector<double>& values, const calibrate::Condition& condition,
                     const EffectContext& context, core::Scene* model, std::string* why) const = 0;
};

}  // namespace demcal::diagnose
