#include "objectives/common/snapshot.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/simulation/simulation.h"

namespace demcal::objectives {

namespace {

double VolumeEquivalentRadius(double mass_kg, double density_kg_m3) {
  return std::cbrt(3.0 * mass_kg / (4.0 * std::numbers::pi * density_kg_m3));
}

}  // namespace

Snapshot TakeSnapshot(const core::Simulation& simulation) {
  const core::Particles& p = simulation.particles();
  const core::Clumps& clumps = simulation.system().clumps;
  const core::Scene& scene = simulation.scene();
  Snapshot snap;
  snap.time_s = simulation.time_s();
  // Free spheres first, then clumps; sorted by id below, with the sphere → grain map fixed up.
  std::vector<int> grain_of_sphere(p.Size(), -1);
  for (size_t i = 0; i < p.Size(); ++i) {
    if (p.body[i] >= 0) continue;
    grain_of_sphere[i] = static_cast<int>(snap.grains.size());
    snap.grains.push_back({p.id[i], p.species[i], p.position_m[i], p.velocity_m_s[i],
                           p.radius_m[i], p.mass_kg[i]});
  }
  for (size_t c = 0; c < clumps.mass_kg.size(); ++c) {
    const int species = clumps.species[c];
    const double density = scene.materials[scene.species[species].material].density_kg_m3;
    const int g = static_cast<int>(snap.grains.size());
    for (uint32_t k = clumps.member_start[c]; k < clumps.member_start[c + 1]; ++k)
      grain_of_sphere[clumps.member_slot[k]] = g;
    snap.grains.push_back({clumps.id[c], species, clumps.position_m[c], clumps.velocity_m_s[c],
                           VolumeEquivalentRadius(clumps.mass_kg[c], density), clumps.mass_kg[c]});
  }
  std::vector<int> order(snap.grains.size());
  for (size_t k = 0; k < order.size(); ++k) order[k] = static_cast<int>(k);
  std::sort(order.begin(), order.end(),
            [&](int a, int b) { return snap.grains[a].id < snap.grains[b].id; });
  std::vector<int> new_index(order.size());
  std::vector<Grain> sorted(order.size());
  for (size_t k = 0; k < order.size(); ++k) {
    new_index[order[k]] = static_cast<int>(k);
    sorted[k] = snap.grains[order[k]];
  }
  snap.grains = std::move(sorted);
  snap.spheres.reserve(p.Size());
  for (size_t i = 0; i < p.Size(); ++i)
    snap.spheres.push_back({p.position_m[i], p.radius_m[i], new_index[grain_of_sphere[i]]});
  return snap;
}

Snapshot Select(const Snapshot& snapshot, const std::function<bool(const Grain&)>& keep) {
  Snapshot out;
  out.time_s = snapshot.time_s;
  std::vector<int> new_index(snapshot.grains.size(), -1);
  for (size_t g = 0; g < snapshot.grains.size(); ++g) {
    if (!keep(snapshot.grains[g])) continue;
    new_index[g] = static_cast<int>(out.grains.size());
    out.grains.push_back(snapshot.grains[g]);
  }
  for (const SurfaceSphere& s : snapshot.spheres) {
    if (new_index[s.grain] < 0) continue;
    out.spheres.push_back({s.position_m, s.radius_m, new_index[s.grain]});
  }
  return out;
}

Snapshot Crop(const Snapshot& snapshot, const Vec3& lo_m, const Vec3& hi_m) {
  return Select(snapshot, [&](const Grain& g) {
    const Vec3& x = g.position_m;
    return x.x >= lo_m.x && x.x <= hi_m.x && x.y >= lo_m.y && x.y <= hi_m.y && x.z >= lo_m.z &&
           x.z <= hi_m.z;
  });
}

}  // namespace demcal::objectives
