#pragma once
// Sinks: where particles leave a simulation on purpose. A particle (a free sphere, or a clump by
// its centre of mass) whose centre crossed a sink plane or entered a sink box is removed and
// counted, per sink and species (number and mass), with the time of the last removal. Fixed
// spheres are never removed. With at least one sink in a scene, a particle that leaves the
// domain box is removed and counted too (under the implicit sink "domain") instead of ending
// the run with "particles_lost": in pours and discharges grains that fly off are expected.
//
// Plane: removed once (x − point_m)·normal > 0 — the normal points where particles go out
// (downwards under a silo's orifice: normal (0, 0, −1)). Box: removed while the centre is inside
// [min_m, max_m].
//
// Removal happens at neighbour rebuilds, at most once per Simulation::Options::sink_every_steps
// steps (the removed mass is counted at that time: a mass-vs-time curve has about that
// resolution). Thread-safety: plain values.
//
// Usage:
//   scene.sinks.push_back(SinkSpec::Plane("below_orifice", {0, 0, -0.02}, {0, 0, -1}));
//   ... sim.Run(t) ...;  for (const SinkReport& r : sim.SinkReports()) r.TotalMassKg();
#include <cstdint>
#include <string>
#include <vector>

#include "core/math/vec3.h"

namespace demcal::core {

struct SinkSpec {
  enum class Shape { kPlane, kBox };
  std::string name;
  Shape shape = Shape::kPlane;
  Vec3 point_m, normal{0, 0, -1};  // plane: a point and the outward unit normal
  Vec3 min_m, max_m;               // box corners

  static SinkSpec Plane(std::string name, const Vec3& point, const Vec3& outward_normal) {
    return {std::move(name), Shape::kPlane, point, outward_normal, {}, {}};
  }
  static SinkSpec Box(std::string name, const Vec3& lo, const Vec3& hi) {
    return {std::move(name), Shape::kBox, {}, {}, lo, hi};
  }
  bool Contains(const Vec3& x) const {
    if (shape == Shape::kPlane) return Dot(x - point_m, normal) > 0;
    return x.x >= min_m.x && x.y >= min_m.y && x.z >= min_m.z && x.x <= max_m.x &&
           x.y <= max_m.y && x.z <= max_m.z;
  }
};

// What one sink has removed so far, per species (indices into Scene::species).
struct SinkReport {
  std::string name;
  std::vector<int64_t> particles;    // per species
  std::vector<double> mass_kg;       // per species
  double last_removal_s = -1;        // simulated time of the last removal (−1: none yet)

  int64_t TotalParticles() const;
  double TotalMassKg() const;
  template <class A>
  void Serialize(A& a) {
    a.Vector(particles), a.Vector(mass_kg), a.Value(last_removal_s);
  }
};

// "" for a valid sink, else the rest of a message after "field 'sinks[i]": "'.normal' must ...".
std::string SinkProblem(const SinkSpec& sink);

// Index of the first sink of `sinks` containing x, or −1. The implicit domain sink (index
// sinks.size()) takes a centre outside [lo, hi] when `domain_sink` is set.
int SinkOf(const std::vector<SinkSpec>& sinks, bool domain_sink, const Vec3& lo, const Vec3& hi,
           const Vec3& x);

}  // namespace demcal::core
