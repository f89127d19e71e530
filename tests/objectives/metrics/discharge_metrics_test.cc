#include "objectives/metrics/discharge_metrics.h"

#include <catch2/catch.hpp>
#include <cmath>

using namespace demcal::objectives;

namespace {

// A synthetic outflow, piecewise linear in time: nothing before the gate opens at t = 1 s, then a
// start-up at 0.5 kg/s for 0.2 s (0.1 kg), a steady 2 kg/s for 2 s (4 kg), a tail at 0.5 kg/s for
// 0.4 s (0.2 kg): 4.3 kg in all. Species 1 makes 10% of the outflow until t = 2.2 s, 5% after.
double Rate(double t) {
  if (t < 1) return 0;
  if (t < 1.2) return 0.5;
  if (t < 3.2) return 2;
  if (t < 3.6) return 0.5;
  return 0;
}
double FractionOfSpecies1(double t) { return t < 2.2 ? 0.1 : 0.05; }

// Samples every 10 ms from 0 to 4 s; the mass per species is the integral of the piecewise
// constant rates (exact at 1 ms sub-steps, whose ends fall on every knot).
std::vector<OutflowSample> SyntheticOutflow() {
  std::vector<OutflowSample> samples;
  double m0 = 0, m1 = 0;
  for (int ms = 0; ms <= 4000; ++ms) {
    if (ms % 10 == 0) samples.push_back({ms * 1e-3, {m0, m1}});
    const double t_mid = (ms + 0.5) * 1e-3;
    m0 += Rate(t_mid) * (1 - FractionOfSpecies1(t_mid)) * 1e-3;
    m1 += Rate(t_mid) * FractionOfSpecies1(t_mid) * 1e-3;
  }
  return samples;
}

}  // namespace

TEST_CASE("discharge: a piecewise-linear outflow gives its rate, time and mass", "[unit]") {
  const DischargeMetrics d = AnalyseDischarge(SyntheticOutflow(), 1.0, {});
  INFO(d.message);
  REQUIRE(d.ok);
  CHECK(d.total_mass_kg == Approx(4.3).epsilon(1e-9));
  // 20%–80% of 4.3 kg (0.86–3.44 kg) lies inside the steady 2 kg/s phase.
  CHECK(d.mass_flow_kg_s == Approx(2.0).epsilon(1e-9));
  CHECK(d.mass_flow_sem_kg_s == Approx(0).margin(1e-9));
  // 99% = 4.257 kg is reached in the tail: 4.1 + 0.5 (t − 3.2) = 4.257 → t = 3.514 s.
  CHECK(d.discharge_time_s == Approx(3.514 - 1.0).epsilon(1e-9));
  // The fitted line, m = 0.1 + 2 (t − 1.2) = −0.3 + 2 (t − 1), over the samples from
  // 0.86 kg (t = 1.58 s) to 3.44 kg (t = 2.87 s), give or take the 10 ms sample at the edge.
  CHECK(d.mass_flow_intercept_kg == Approx(-0.3).epsilon(1e-9));
  CHECK(d.flow_window_start_s == Approx(1.58).margin(0.0101));
  CHECK(d.flow_window_end_s == Approx(2.87).margin(0.0101));
}

TEST_CASE("discharge: composition bins follow a known change of the mixture", "[unit]") {
  DischargeOptions options;
  options.composition_bin_s = 0.2;
  const DischargeMetrics d = AnalyseDischarge(SyntheticOutflow(), 1.0, options);
  REQUIRE(d.ok);
  // Bins of 0.2 s from 1 s to 3.514 s: 12 full ones and a clipped last one.
  REQUIRE(d.composition.size() == 13);
  CHECK(d.composition.back().t_end_s == Approx(3.514).epsilon(1e-9));
  double mass = 0;
  for (const CompositionBin& bin : d.composition) {
    mass += bin.mass_kg;
    const double expected = bin.t_end_s <= 2.2 + 1e-9 ? 0.1 : 0.05;
    CHECK(bin.mass_fraction[1] == Approx(expected).epsilon(1e-9));
    CHECK(bin.mass_fraction[0] + bin.mass_fraction[1] == Approx(1).epsilon(1e-12));
  }
  CHECK(d.composition[0].mass_kg == Approx(0.1).epsilon(1e-9));  // start-up 1–1.2 s
  CHECK(d.composition[1].mass_kg == Approx(0.4).epsilon(1e-9));  // steady 2 kg/s × 0.2 s
  CHECK(mass == Approx(0.99 * 4.3).epsilon(1e-9));
}

TEST_CASE("discharge: the default 20 bins span the discharge", "[unit]") {
  const DischargeMetrics d = AnalyseDischarge(SyntheticOutflow(), 1.0, {});
  REQUIRE(d.ok);
  REQUIRE(d.composition.size() == 20);
  CHECK(d.composition.front().t_start_s == 1.0);
  CHECK(d.composition.back().t_end_s == Approx(1.0 + d.discharge_time_s).epsilon(1e-12));
}

TEST_CASE("discharge: unusable input is refused with a message", "[unit]") {
  const std::vector<OutflowSample> good = SyntheticOutflow();
  auto refused = [](const DischargeMetrics& d, const std::string& part) {
    INFO(d.message);
    return !d.ok && d.message.find(part) != std::string::npos;
  };
  CHECK(refused(AnalyseDischarge({}, 0, {}), "at least 2"));
  std::vector<OutflowSample> backwards = good;
  backwards[100].time_s = backwards[99].time_s;
  CHECK(refused(AnalyseDischarge(backwards, 1, {}), "not increasing"));
  std::vector<OutflowSample> decreasing = good;
  decreasing[300].cumulative_mass_kg[0] = 0;
  CHECK(refused(AnalyseDischarge(decreasing, 1, {}), "decreases"));
  std::vector<OutflowSample> ragged = good;
  ragged[5].cumulative_mass_kg.push_back(0);
  CHECK(refused(AnalyseDischarge(ragged, 1, {}), "species count"));
  CHECK(refused(AnalyseDischarge(good, 5, {}), "gate_open_s"));
  CHECK(refused(AnalyseDischarge(good, 3.9, {}), "no mass"));
  CHECK(refused(AnalyseDischarge(good, 1, {.expected_total_mass_kg = 10}), "incomplete"));
  CHECK(refused(AnalyseDischarge(good, 1, {.flow_window_low = 0.9, .flow_window_high = 0.5}),
                "flow_window_low"));
  const std::vector<OutflowSample> sparse = {{0, {0}}, {1, {0.5}}, {2, {1}}};
  CHECK(refused(AnalyseDischarge(sparse, 0, {}), "flow window"));
}
