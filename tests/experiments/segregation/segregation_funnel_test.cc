// The segregation heap's funnel meters the flow when it is fed faster than its orifice passes:
// its steady outflow is then the orifice's (Beverloo: W = C ρ_b √g (D − k d)^{5/2}, independent of
// the head and of the feed: Beverloo, Leniger & van de Velde 1961; Nedderman 1992, ch. 10), and
// the run says "orifice_limited"; fed slower, it passes the feed as it comes ("feed_limited").
//
// Set-up: one species of 2 mm spheres (780 kg/m³, the BP density; μ 0.5, μr 0, e 0.5) and a
// funnel with a 12 mm orifice (6 d) in the paper's 16 mm deep box. Beverloo with C 0.5, k 1.5 and
// ρ_b ≈ 0.6 · 780 puts the orifice's capacity near 6 g/s (measured: 7.7–8.0 g/s): a 4 g feed at 20
// and 40 g/s backs up in the funnel, one at 4 g/s does not.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "experiments/segregation/segregation_experiment.h"
#include "objectives/common/replicates.h"

namespace demcal::objectives {
namespace {

core::Scene Spheres() {
  core::Scene m;
  for (const auto& [name, density] : {std::pair{"grain", 780.0}, {"wall", 1180.0}})
    m.materials.push_back({name, core::Material::YoungsFromShear(1e6, 0.25), 0.25, density});
  core::Species s;
  s.name = "grain";
  s.size.kind = core::SizeDistribution::Kind::kFixed;
  s.size.diameter_m = 0.002;
  m.species = {s};
  m.pair_parameters.assign(4, core::PairParameters{});  // μs 0.5, e 0.5, μr 0
  return m;
}

SegregationSettings FunnelOnly(double feed_rate_kg_s) {
  SegregationSettings s;
  s.feed.components = {{0, 1.0}};
  s.feed.mass_kg = 0.004;
  s.feed.mass_rate_kg_s = feed_rate_kg_s;
  s.width_m = 0.08;
  s.depth_m = 0.016;
  s.pour_height_m = 0.035;  // above the ≈ 16 mm heap the 4 g make below it
  s.feed_width_m = 0.03;
  s.funnel = {
      .enabled = true, .orifice_diameter_m = 0.012, .top_diameter_m = 0.05, .height_m = 0.03};
  s.wall_material = 1;
  s.glued_base = false;
  // The run only has to outlast the funnel (the orifice passes 4 g in ≈ 0.5 s): it ends 0.8 s
  // after the feed, settled or not; the funnel's clock is read either way.
  s.settle.max_time_s = s.feed.DurationS() + 0.8;
  s.settle.specific_kinetic_J_kg = 1e-4;
  s.tracking.granules = 0;
  s.segregation.random.repetitions = 10;
  s.floor.shuffles = 20;
  return s;
}

}  // namespace

TEST_CASE("segregation funnel: fed faster than its orifice, the orifice sets the rate",
          "[physics]") {
  const core::Scene model = Spheres();
  const std::vector<double> rates = {0.02, 0.04, 0.004};  // kg/s
  std::vector<SegregationRun> runs(rates.size());
  for (double rate : rates) {
    std::string error;
    INFO("feed " << rate << " kg/s: " << error);
    REQUIRE(FunnelOnly(rate).IsValid(model, &error));
  }
  RunReplicates(static_cast<int>(rates.size()), 5 + Catch::rngSeed(), 2, [&](int r, uint64_t seed) {
    runs[r] = RunSegregation(model, FunnelOnly(rates[r]), seed, {});
  });
  for (size_t i = 0; i < rates.size(); ++i) {
    std::printf("funnel check: feed %.3f kg/s  regime %s  discharge %.3f s  steady %.4f kg/s  "
                "(%.1f s wall)\n",
                rates[i], runs[i].funnel_regime.c_str(), runs[i].discharge_time_s,
                runs[i].funnel_mass_flow_kg_s, runs[i].wall_time_s);
    REQUIRE(runs[i].funnel_emptied);
  }
  const SegregationRun &fast = runs[0], &faster = runs[1], &slow = runs[2];
  CHECK(fast.funnel_regime == "orifice_limited");
  CHECK(faster.funnel_regime == "orifice_limited");
  CHECK_FALSE(fast.funnel_feed_limited);
  // The orifice's rate, not the feed's: doubling the feed leaves it within 15 %. Over --rng-seed
  // 0–3 one run's steady flow scattered by 3.4 % (standard deviation) with a 2 g feed and stayed
  // within 7.7–8.0 g/s with these 4 g (both feeds); 15 % allows for the 2 g scatter's difference
  // of two runs (≈ 5 %) three times over. Wall time ≈ 20 s per run on a loaded 2-core machine.
  CHECK(fast.funnel_mass_flow_kg_s < 0.5 * rates[0]);
  CHECK(faster.funnel_mass_flow_kg_s == Approx(fast.funnel_mass_flow_kg_s).epsilon(0.15));
  // ... and a feed slower than the orifice passes through at its own rate (within 10 %: the
  // factory's rate is exact, the window sees its batches).
  CHECK(slow.funnel_regime == "feed_limited");
  CHECK(slow.funnel_feed_limited);
  CHECK(slow.funnel_mass_flow_kg_s == Approx(rates[2]).epsilon(0.1));
  CHECK(slow.funnel_mass_flow_kg_s < fast.funnel_mass_flow_kg_s);
}

}  // namespace demcal::objectives
