#include "objectives/metrics/granule_tracking.h"

#include <catch2/catch.hpp>
#include <cmath>

using namespace demcal::objectives;

namespace {

constexpr int64_t kTracked = 100;

// A flat heap surface: a row of resting spheres (r = 5 mm) with tops at z = 0.1 m.
Snapshot FlatSurface() {
  Snapshot snap;
  for (int i = 0; i <= 20; ++i) {
    const int index = static_cast<int>(snap.grains.size());
    snap.grains.push_back({i, 0, {0.01 * i, 0, 0.095}, {}, 0.005, 1e-3});
    snap.spheres.push_back({{0.01 * i, 0, 0.095}, 0.005, index});
  }
  return snap;
}

void AddGrain(Snapshot& snap, int64_t id, const demcal::core::Vec3& position_m,
              const demcal::core::Vec3& velocity_m_s, double radius_m) {
  const int index = static_cast<int>(snap.grains.size());
  snap.grains.push_back({id, 2, position_m, velocity_m_s, radius_m, 1e-4});
  snap.spheres.push_back({position_m, radius_m, index});
}

}  // namespace

TEST_CASE("penetration depth is measured below the local surface", "[unit]") {
  // Figs. 17–18: how deep a granule ends below the heap surface.
  Snapshot snap = FlatSurface();
  AddGrain(snap, kTracked, {0.1, 0, 0.07}, {}, 0.003);
  AddGrain(snap, 200, {0.101, 0, 0.2}, {0, 0, -2.0}, 0.005);  // falling: not the surface
  std::string error;
  const auto depth = PenetrationDepth(snap, kTracked, {}, &error);
  REQUIRE(depth);
  CHECK(depth->surface_height_m == Approx(0.1));
  CHECK(depth->depth_m == Approx(0.03));
  CHECK(depth->depth_diameters == Approx(5.0));
  CHECK_FALSE(PenetrationDepth(snap, 999, {}, &error));
  CHECK(error.find("999") != std::string::npos);
  // The column is 2 tracked diameters wide (12 mm): only spheres within 6 mm of x count.
  CHECK(SurfaceHeightAt(snap, 0.3, 0.012, 0.5) == std::nullopt);
}

TEST_CASE("a falling granule's impact is found by speed drop and surface approach", "[unit]") {
  // Fig. 19: specific kinetic energy ½v² of a granule falling freely onto the heap, stopping
  // at the surface. Free fall from z = 0.3 m: the bottom (r = 3 mm) reaches the surface at 0.1 m.
  const double g = 9.81, r = 0.003, z0 = 0.3;
  const double t_hit = std::sqrt(2 * (z0 - 0.1 - r) / g);
  std::vector<Snapshot> series;
  for (int step = 0; step <= 40; ++step) {
    const double t = 0.01 * step;
    Snapshot snap = FlatSurface();
    snap.time_s = t;
    const bool falling = t < t_hit;
    const double z = falling ? z0 - 0.5 * g * t * t : 0.1 + r;
    AddGrain(snap, kTracked, {0.1, 0, z}, {0, 0, falling ? -g * t : 0.0}, r);
    series.push_back(snap);
  }
  const auto tracks = TrackGranules(series, {kTracked, 555}, {});
  REQUIRE(tracks.size() == 2);
  CHECK(tracks[1].samples.empty());
  const GranuleTrack& track = tracks[0];
  REQUIRE(track.samples.size() == 41);
  CHECK(track.species == 2);
  CHECK(track.samples[10].SpecificKineticEnergyJPerKg() == Approx(0.5 * std::pow(g * 0.1, 2)));
  const auto drop = FirstSpeedDropIndex(track, {});
  REQUIRE(drop);
  CHECK(track.samples[*drop].time_s == Approx(std::ceil(t_hit / 0.01) * 0.01));
  const auto approach = FirstSurfaceApproachIndex(track, {});
  REQUIRE(approach);
  // Within one diameter (6 mm) above the surface: at most one sample before the impact.
  CHECK(*approach <= *drop);
  CHECK(*approach >= *drop - 1);
  CHECK(track.samples[*approach].surface_height_m == Approx(0.1));
  // A grain that never falls fast has no impact.
  GranuleTrack resting = track;
  for (GranuleSample& s : resting.samples) s.velocity_m_s = {0, 0, -0.01};
  CHECK_FALSE(FirstSpeedDropIndex(resting, {}));
}
