// The paper's mechanism observables (section 3.5, Figs. 17, 19) on hand-made states: the landing
// depth, the specific kinetic energy after the first impact, the contacts per grain and the
// offset from the heap's axis, each worked out by hand from the constructed samples or grains.
#include <catch2/catch.hpp>

#include "experiments/segregation/mechanism/axis_offset.h"
#include "experiments/segregation/mechanism/contacts_per_grain.h"
#include "experiments/segregation/mechanism/impact_kinetic_energy.h"
#include "experiments/segregation/mechanism/landing_depth.h"
#include "experiments/segregation/mechanism/mechanism_observables.h"

namespace demcal::objectives {
namespace {

GranuleSample Sample(double t, double speed, double z, double surface) {
  GranuleSample s;
  s.time_s = t;
  s.velocity_m_s = {0, 0, -speed};
  s.position_m = {0.1, 0.008, z};
  s.radius_m = 0.0005;
  s.has_surface = true;
  s.surface_height_m = surface;
  return s;
}

// Falls at 1.5 m/s, hits at sample 2 (0.4 m/s), rolls at 0.2 m/s, rests from sample 5 at
// z = 0.0465 under a surface at 0.05: landing depth 3.5 mm. Samples every 2 ms.
TrackedGranule Landing() {
  TrackedGranule g;
  const double speed[] = {1.5, 1.5, 0.4, 0.2, 0.2, 0.01, 0.0};
  const double z[] = {0.08, 0.06, 0.051, 0.050, 0.048, 0.0465, 0.0465};
  for (int k = 0; k < 7; ++k)
    g.track.samples.push_back(Sample(0.1 + 0.002 * k, speed[k], z[k], 0.05));
  g.impact_sample = 2;
  return g;
}

TEST_CASE("landing depth: below the surface at the first rest after the impact", "[unit]") {
  TrackedGranule g = Landing();
  REQUIRE(LandingDepthM(g, {}));
  CHECK(*LandingDepthM(g, {}) == Approx(0.0035).margin(1e-12));
  // A stricter rest speed moves the landing to the sample at 0 m/s (same height here).
  CHECK(*LandingDepthM(g, {.rest_speed_m_s = 0.005}) == Approx(0.0035).margin(1e-12));
  // A grain resting on top of the surface (centre one radius above it) has depth −r.
  g.track.samples[5].position_m.z = 0.0505;
  CHECK(*LandingDepthM(g, {}) == Approx(-0.0005).margin(1e-12));
  // No column surface at rest: that sample is skipped, the next one counts.
  g.track.samples[5].has_surface = false;
  g.track.samples[6].surface_height_m = 0.052;
  CHECK(*LandingDepthM(g, {}) == Approx(0.052 - 0.0465).margin(1e-12));
  // Never at rest, or no impact: no landing depth.
  CHECK_FALSE(LandingDepthM(g, {.rest_speed_m_s = 0.0}));
  g.impact_sample.reset();
  CHECK_FALSE(LandingDepthM(g, {}));
}

TEST_CASE("after-impact specific kinetic energy: mean 1/2 v^2 over the window after impact",
          "[unit]") {
  TrackedGranule g;
  // Impact at sample 0 with 2 m/s (1/2 v^2 = 2 J/kg), then at rest; 2 ms samples.
  g.track.samples.push_back(Sample(0.2, 2.0, 0.05, 0.05));
  for (int k = 1; k < 30; ++k) g.track.samples.push_back(Sample(0.2 + 0.002 * k, 0.0, 0.05, 0.05));
  g.impact_sample = 0;
  // Window 19 ms holds samples 0..9: (2 + 9 × 0) / 10.
  CHECK(*AfterImpactSpecificKineticJKg(g, {.window_s = 0.019}) == Approx(0.2));
  // Window 0: the impact sample alone.
  CHECK(*AfterImpactSpecificKineticJKg(g, {.window_s = 0.0}) == Approx(2.0));
  // A grain that keeps rolling at 1 m/s after the impact keeps 1/2 J/kg.
  for (size_t k = 1; k < g.track.samples.size(); ++k) g.track.samples[k].velocity_m_s = {1, 0, 0};
  CHECK(*AfterImpactSpecificKineticJKg(g, {.window_s = 0.019}) == Approx((2 + 9 * 0.5) / 10));
  g.impact_sample.reset();
  CHECK_FALSE(AfterImpactSpecificKineticJKg(g, {}));
}

// Grain 0: EP sphere r = 1 mm at the origin; grain 1: BP sphere touching it (centres 1.999 mm);
// grain 2: a BP two-sphere clump, both spheres touching (one contact); grain 3: BP at 1.05×
// contact distance (not touching); grain 4: TAED touching (not BP); grain 5: EP far away.
Snapshot HandMadeHeap() {
  Snapshot s;
  const int kEp = 2, kBp = 0, kTaed = 1;
  const int species[] = {kEp, kBp, kBp, kBp, kTaed, kEp};
  const double x[] = {0, 0.001999, 0, -0.0021, 0, 0.05};  // the grains' centres along x
  for (int k = 0; k < 6; ++k)
    s.grains.push_back({.id = k, .species = species[k], .position_m = {x[k], 0, 0},
                        .radius_m = 0.001, .mass_kg = 1e-6});
  s.spheres = {{{0, 0, 0}, 0.001, 0},
               {{0.001999, 0, 0}, 0.001, 1},
               {{0, 0.0015, 0.0013}, 0.001, 2},
               {{0, 0.0015, -0.0013}, 0.001, 2},
               {{-0.0021, 0, 0}, 0.001, 3},
               {{0, -0.001999, 0}, 0.001, 4},
               {{0.05, 0.05, 0.05}, 0.001, 5}};
  return s;
}

TEST_CASE("contacts per grain: partner grains touching, each clump once", "[unit]") {
  const Snapshot heap = HandMadeHeap();
  // EP grains: 2 BP contacts and 0: mean 1.
  CHECK(*ContactsPerGrain(heap, 2, 0, {}) == Approx(1.0));
  CHECK(*ContactsPerGrain(heap, 2, 1, {}) == Approx(0.5));
  // A 10 % gap admits grain 3 (1.05× the contact distance): 3 and 0 contacts.
  CHECK(*ContactsPerGrain(heap, 2, 0, {.gap_fraction = 0.1}) == Approx(1.5));
  CHECK_FALSE(ContactsPerGrain(heap, 7, 0, {}));
}

// BP grains at x = c ± 1 mm and c ± 3 mm (mean distance 2 mm from the axis at c).
Snapshot Row(const std::vector<double>& ep_offsets_mm) {
  Snapshot s;
  const double c = 0.1;
  int64_t id = 0;
  for (double dx : {-3.0, -1.0, 1.0, 3.0})
    s.grains.push_back({.id = id++, .species = 0, .position_m = {c + dx / 1000, 0, 0},
                        .mass_kg = 1e-6});
  for (double dx : ep_offsets_mm)
    s.grains.push_back({.id = id++, .species = 2, .position_m = {c + dx / 1000, 0, 0},
                        .mass_kg = 1e-6});
  return s;
}

TEST_CASE("axis offset: the tracked grains' distance from the heap's axis over the bulk's",
          "[unit]") {
  // Centred EP (|x| 1 mm against BP's 2 mm): −0.5; at the toes (4 mm): +1; spread as BP: 0.
  CHECK(*AxisOffset(Row({-1, 1}), 2, 0) == Approx(-0.5));
  CHECK(*AxisOffset(Row({-4, 4}), 2, 0) == Approx(1.0));
  CHECK(*AxisOffset(Row({-3, -1, 1, 3}), 2, 0) == Approx(0.0).margin(1e-12));
  // The axis is the heap's centre of mass: an EP grain at +4 mm as heavy as the four BP pulls it
  // to +2 mm; the BP grains are then 5, 3, 1, 1 mm away (mean 2.5) and the EP grain 2 mm.
  Snapshot heavy = Row({4});
  heavy.grains.back().mass_kg = 4e-6;  // as heavy as the four BP: centre (4 × 4 mm) / 8
  CHECK(*AxisOffset(heavy, 2, 0) == Approx(2.0 / 2.5 - 1));
  // No tracked or no major grain: no value.
  CHECK_FALSE(AxisOffset(Row({}), 2, 0));
  CHECK_FALSE(AxisOffset(Row({1}), 2, 7));
}

TEST_CASE("mechanism registry: unit in every name, per-run values from the run's own state",
          "[unit]") {
  SegregationSettings settings;
  settings.feed.components = {{0, 0.925}, {1, 0.055}, {2, 0.02}};
  CHECK(MajorSpecies(settings) == 0);
  CHECK(settings.TrackedSpecies() == 2);
  SegregationRun run;
  run.heap = HandMadeHeap();
  run.tracked = {Landing(), Landing()};
  run.tracked[1].impact_sample.reset();  // no impact: no value; the mean is over the other
  for (const MechanismObservable& o : MechanismObservables()) {
    const std::string name = o.name;
    CHECK((name.ends_with("_m") || name.ends_with("_J_kg") || name.ends_with("_per_grain") ||
           name.ends_with("_fraction")));
    const std::optional<double> v = o.per_run(run, settings);
    REQUIRE(v);
    if (name == "tracked_landing_depth_m") CHECK(*v == Approx(0.0035).margin(1e-12));
    if (name == "tracked_major_contacts_per_grain") CHECK(*v == Approx(1.0));
    if (name == "tracked_axis_offset_fraction")
      CHECK(*v == Approx(*AxisOffset(run.heap, 2, 0)));
    // Impact at sample 2 (t = 0.104 s); samples 2..6 lie within its 20 ms window.
    if (name == "tracked_after_impact_specific_kinetic_J_kg")
      CHECK(*v == Approx((0.08 + 0.02 + 0.02 + 0.00005 + 0) / 5));
  }
  CHECK(MechanismObservables().size() == 4);
}

}  // namespace
}  // namespace demcal::objectives
