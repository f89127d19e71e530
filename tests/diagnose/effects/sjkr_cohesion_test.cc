// The sjkr_cohesion candidate (diagnose/effects/sjkr_cohesion.cc): its probe is the k the LIGGGHTS
// export maps jkr_adhesion's probe Γ to (k = F_c/(π a0²), docs/export.md), its bound three times
// that, its value follows the coating column, and it is a law of the same mechanism as JKR.
#include <catch2/catch.hpp>
#include <numbers>

#include "calibrate/liggghts_export.h"
#include "diagnose/effects/effect_registry.h"
#include "diagnose/effects/effect_support.h"

namespace demcal::diagnose {
namespace {

constexpr double kEStar = 1.3333333e8, kRStar = 115.625e-6;  // BP's self-contact, Pa and m

core::Scene Model() {
  core::Scene m;
  m.materials = {{"BP", 2.5e8, 0.25, 780}, {"perspex", 2.5e9, 0.25, 1180}};
  m.species = {{"BP", 0}};
  m.pair_parameters.assign(4, {0.5, 0.1, 0.2, 0.0});
  return m;
}

EffectContext Context() {
  EffectContext c{"BP", "BP", {"perspex"}, "coating_PEG_wt_pct", 3.0};
  c.self_effective_youngs_Pa = kEStar;
  c.self_effective_radius_m = kRStar;
  return c;
}

}  // namespace

TEST_CASE("sjkr_cohesion probes at the exporter's k for JKR's probe, per unit of coating",
          "[unit]") {
  const Effect* e = FindEffect("sjkr_cohesion");
  REQUIRE(e);
  CHECK(e->Mechanism() == "adhesion");
  CHECK(FindEffect("jkr_adhesion")->Mechanism() == "adhesion");
  CHECK(FindEffect("rolling_resistance")->Mechanism() == "rolling_resistance");
  const EffectParameter p = e->Parameters(Context())[0];
  CHECK(p.name == "k_per_coating_PEG_wt_pct_J_m3");
  CHECK(p.unit == "J/m3");
  // JKR (Johnson, Kendall & Roberts 1971): F_c = 3πΓR* (w = 2Γ), a0³ = 9πΓR*²/E*.
  const double pi = std::numbers::pi, gamma = kJkrProbeGamma_J_m2;
  const double a0 = std::cbrt(9 * pi * gamma * kRStar * kRStar / kEStar);
  const double k = 3 * pi * gamma * kRStar / (pi * a0 * a0);
  CHECK(p.probe * 3.0 == Approx(k).epsilon(1e-12));
  CHECK(p.upper == Approx(3 * p.probe));
  CHECK(p.lower == 0);  // no cohesion in the base to take away
  EffectContext c = Context();
  c.cohesion_energy_density = 600;
  CHECK(e->Parameters(c)[0].lower == Approx(-200));  // k at 3 wt% = 600 + 3·q >= 0
  CHECK(e->Parameters(c)[0].less == "less cohesion than assumed");
}

TEST_CASE("sjkr_cohesion writes k = q·w into the species' self-contact only", "[unit]") {
  const Effect* e = FindEffect("sjkr_cohesion");
  std::string why;
  core::Scene m = Model();
  REQUIRE(e->Apply({5000}, {{"coating_PEG_wt_pct", "1.5"}}, Context(), &m, &why));
  CHECK(m.pair_parameters[0].cohesion_energy_density_J_m3 == Approx(7500));
  CHECK(m.pair_parameters[1].cohesion_energy_density_J_m3 == 0);  // BP-perspex untouched
  CHECK(m.pair_parameters[0].interfacial_energy_J_m2 == 0);
  m = Model();
  REQUIRE(e->Apply({5000}, {{"coating_PEG_wt_pct", "0"}}, Context(), &m, &why));
  CHECK(m.pair_parameters[0].cohesion_energy_density_J_m3 == 0);
  m = Model();
  CHECK_FALSE(e->Apply({-1}, {{"coating_PEG_wt_pct", "3"}}, Context(), &m, &why));
  CHECK(why.find("cohesion_energy_density_J_m3 of BP-BP") != std::string::npos);
  // On a model with JKR adhesion (here BP-perspex), sjkr would make a scene of two laws.
  m = Model();
  m.pair_parameters[1].interfacial_energy_J_m2 = m.pair_parameters[2].interfacial_energy_J_m2 =
      0.01;
  CHECK_FALSE(e->Apply({5000}, {{"coating_PEG_wt_pct", "3"}}, Context(), &m, &why));
  CHECK(why == "the model would call for two adhesion laws, jkr and sjkr; a scene runs one");
  m = Model();
  m.pair_parameters[0].cohesion_energy_density_J_m3 = 100;
  CHECK_FALSE(FindEffect("jkr_adhesion")
                  ->Apply({0.004}, {{"coating_PEG_wt_pct", "3"}}, Context(), &m, &why));
  CHECK(why.find("two adhesion laws") != std::string::npos);
}

}  // namespace demcal::diagnose
