// Size polydispersity: the subject species' size distribution widens (or narrows, down to one
// diameter) about the same mean diameter. The relative width w = (d_max − d_min) / d_mean of its
// uniform sieve cut (a single diameter counts as w = 0) becomes w + Δ; diameters stay uniform in
// [d_mean(1 − w/2), d_mean(1 + w/2)]. A wider distribution packs denser (small grains fill the
// gaps) and flows differently; the repose angle moves little. Probe Δ = 0.8; w stays below 1.8
// (d_min > 0).
#include "diagnose/effects/effect_registry.h"
#include "diagnose/effects/effect_support.h"

namespace demcal::diagnose {
namespace {

constexpr double kMaxWidth = 1.8;

class SizePolydispersity final : public Effect {
 public:
  std::string Key() const override { return "size_polydispersity"; }
  std::string Description() const override {
    return "size polydispersity: relative width (d_max - d_min)/d_mean of the species' size cut "
           "widened by "
           "delta_relative_width about the same mean";
  }
  std::vector<EffectParameter> Parameters(const EffectContext& c) const override {
    // Down to a single diameter (w = 0) at the base's width.
    return {{"delta_relative_width", "", -c.relative_width, 1.4, 0.8,
             "a wider size distribution than assumed",
             c.relative_width > 0 ? "a narrower size distribution than assumed" : "",
             c.relative_width}};
  }
  bool Apply(const std::vector<double>& v, const calibrate::Condition&, const EffectContext& c,
             core::Scene* model, std::string* why) const override {
    int s = 0;
    if (!FindSpecies(*model, c, &s, why)) return false;
    if (v[0] == 0) return true;
    core::SizeDistribution& size = model->species[s].size;
    using Kind = core::SizeDistribution::Kind;
    if (size.kind == Kind::kTable)
      return *why = "species '" + c.species + "' has a size table", false;
    const double lo = size.kind == Kind::kFixed ? size.diameter_m : size.min_diameter_m;
    const double hi = size.kind == Kind::kFixed ? size.diameter_m : size.max_diameter_m;
    const double mean = 0.5 * (lo + hi), width = (hi - lo) / mean + v[0];
    if (!(width >= 0 && width < kMaxWidth))
      return *why = "relative width " + std::to_string(width) + " outside [0, " +
                    std::to_string(kMaxWidth) + ")",
             false;
    size.kind = Kind::kUniform;
    size.min_diameter_m = mean * (1 - 0.5 * width);
    size.max_diameter_m = mean * (1 + 0.5 * width);
    return true;
  }
};

}  // namespace

const Effect* SizePolydispersityEffect() {
  static const SizePolydispersity effect;
  return &effect;
}

}  // namespace demcal::diagnose
