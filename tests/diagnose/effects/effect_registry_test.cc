#include "diagnose/effects/effect_registry.h"

#include <catch2/catch.hpp>
#include <set>

namespace demcal::diagnose {
namespace {

// BP (uniform 425-500 µm) and a perspex wall, μs 0.5 / μr 0.1 everywhere.
core::Scene Model() {
  core::Scene m;
  m.materials = {{"BP", 2.5e8, 0.25, 780}, {"perspex", 2.5e9, 0.25, 1180}};
  core::Species bp{"BP", 0};
  bp.size.kind = core::SizeDistribution::Kind::kUniform;
  bp.size.min_diameter_m = 425e-6;
  bp.size.max_diameter_m = 500e-6;
  m.species = {bp};
  m.pair_parameters.assign(4, {0.5, 0.1, 0.2, 0.0});
  return m;
}

// With the self-contact E* and R* MakeEffectContext derives from Model() (E/(2(1 − ν²)), half
// the mean radius), which the sjkr candidate converts its probe with.
EffectContext Context() {
  EffectContext c{"BP", "BP", {"perspex"}, "coating_PEG_wt_pct", 3.0};
  c.self_effective_youngs_Pa = 2.5e8 / (2 * (1 - 0.25 * 0.25));
  c.self_effective_radius_m = 0.5 * 231.25e-6;
  return c;
}

}  // namespace

TEST_CASE("effect library: every effect is off at 0 and declares a probe inside its bounds",
          "[unit]") {
  std::set<std::string> keys;
  for (const Effect* e : EffectLibrary()) {
    INFO(e->Key());
    keys.insert(e->Key());
    CHECK(FindEffect(e->Key()) == e);
    const std::vector<EffectParameter> p = e->Parameters(Context());
    REQUIRE(p.size() == 1);
    CHECK(p[0].lower <= 0);
    CHECK(p[0].upper > p[0].probe);
    CHECK(p[0].probe > p[0].lower);
    core::Scene m = Model();
    std::string why;
    REQUIRE(e->Apply({0.0}, {{"coating_PEG_wt_pct", "3"}}, Context(), &m, &why));
    CHECK(m.pair_parameters[0].sliding_friction == 0.5);
    CHECK(m.pair_parameters[0].interfacial_energy_J_m2 == 0);
    CHECK(m.pair_parameters[0].cohesion_energy_density_J_m3 == 0);
    CHECK(m.species[0].clump_shape.empty());
    CHECK(m.species[0].size.max_diameter_m == 500e-6);
  }
  CHECK(keys.size() == 7);
  CHECK(FindEffect("nonsense") == nullptr);
}

TEST_CASE("signed effects may weaken what the base assumes, down to the physical bound", "[unit]") {
  // The base model of Model(): μs 0.5, μr 0.1, μw 0.5, no adhesion, width 0.162 (425-500 µm).
  EffectContext c = Context();
  c.sliding_friction = 0.5, c.rolling_friction = 0.1, c.wall_friction = 0.5;
  c.relative_width = 75.0 / 462.5;
  auto lower = [&c](const std::string& key) { return FindEffect(key)->Parameters(c)[0].lower; };
  CHECK(lower("rolling_resistance") == Approx(-0.1));
  CHECK(lower("wall_friction") == Approx(-0.5));
  CHECK(lower("size_polydispersity") == Approx(-75.0 / 462.5));
  CHECK(lower("sliding_friction_control") == Approx(-0.5));
  CHECK(lower("jkr_adhesion") == 0);    // the base has no adhesion to take away
  CHECK(lower("particle_shape") == 0);  // a sphere: nothing is rounder
  const EffectParameter rolling = FindEffect("rolling_resistance")->Parameters(c)[0];
  CHECK(EffectDirection(rolling, -0.05) == "less rolling resistance than assumed");
  CHECK(EffectDirection(rolling, 0.05) == "more rolling resistance than assumed");
  c.interfacial_energy = 0.006;  // Γ at the largest coating level 3 is 0.006 + 3·g >= 0
  CHECK(lower("jkr_adhesion") == Approx(-0.002));
  // At the lower bound the property reaches its physical limit; beyond it Apply refuses.
  std::string why;
  core::Scene m = Model();
  REQUIRE(FindEffect("rolling_resistance")->Apply({-0.1}, {}, c, &m, &why));
  CHECK(m.pair_parameters[0].rolling_friction == Approx(0.0).margin(1e-15));
  m = Model();
  CHECK_FALSE(FindEffect("rolling_resistance")->Apply({-0.11}, {}, c, &m, &why));
  CHECK(why.find("rolling_friction") != std::string::npos);
  m = Model();
  REQUIRE(FindEffect("size_polydispersity")->Apply({-0.1}, {}, c, &m, &why));
  const core::SizeDistribution& s = m.species[0].size;
  CHECK((s.max_diameter_m - s.min_diameter_m) / 462.5e-6 == Approx(0.062).epsilon(1e-2));
  m = Model();
  REQUIRE(FindEffect("wall_friction")->Apply({-0.3}, {}, c, &m, &why));
  CHECK(m.pair_parameters[1].sliding_friction == Approx(0.2));
}

TEST_CASE("effects write what they declare into the model", "[unit]") {
  std::string why;
  core::Scene m = Model();
  // Adhesion follows the coating column: Γ = g·w, nothing for uncoated material.
  REQUIRE(FindEffect("jkr_adhesion")
              ->Apply({0.004}, {{"coating_PEG_wt_pct", "1.5"}}, Context(), &m, &why));
  CHECK(m.pair_parameters[0].interfacial_energy_J_m2 == Approx(0.006));
  CHECK(m.pair_parameters[1].interfacial_energy_J_m2 == 0);  // BP-perspex untouched
  m = Model();
  REQUIRE(FindEffect("jkr_adhesion")
              ->Apply({0.004}, {{"coating_PEG_wt_pct", "0"}}, Context(), &m, &why));
  CHECK(m.pair_parameters[0].interfacial_energy_J_m2 == 0);
  m = Model();
  REQUIRE(FindEffect("rolling_resistance")->Apply({0.3}, {}, Context(), &m, &why));
  CHECK(m.pair_parameters[0].rolling_friction == Approx(0.4));
  m = Model();
  REQUIRE(FindEffect("wall_friction")->Apply({0.2}, {}, Context(), &m, &why));
  CHECK(m.pair_parameters[1].sliding_friction == Approx(0.7));
  CHECK(m.pair_parameters[2].sliding_friction == Approx(0.7));
  CHECK(m.pair_parameters[0].sliding_friction == Approx(0.5));
  m = Model();
  REQUIRE(FindEffect("particle_shape")->Apply({1.0}, {}, Context(), &m, &why));
  CHECK(m.species[0].clump_shape.size() == 3);
  m = Model();
  REQUIRE(FindEffect("size_polydispersity")->Apply({0.973}, {}, Context(), &m, &why));
  const core::SizeDistribution& s = m.species[0].size;
  CHECK(0.5 * (s.min_diameter_m + s.max_diameter_m) == Approx(462.5e-6));
  CHECK((s.max_diameter_m - s.min_diameter_m) / 462.5e-6 == Approx(0.162 + 0.973).epsilon(1e-3));
  // Out of range: a clear reason, never a silent clamp.
  m = Model();
  CHECK_FALSE(FindEffect("sliding_friction_control")->Apply({-0.6}, {}, Context(), &m, &why));
  CHECK(why.find("sliding_friction") != std::string::npos);
}

}  // namespace demcal::diagnose
