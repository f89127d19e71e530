#include "core/bodies/particle_system.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <numeric>

#include "core/bodies/unit_clump.h"

namespace demcal::core {

bool ParticleSystem::SetSpecies(const std::vector<Species>& species, std::string* error) {
  shapes.assign(species.size(), ClumpTemplate{});
  for (size_t s = 0; s < species.size(); ++s) {
    if (species[s].clump_shape.empty()) continue;
    std::string why;
    if (!UnitDiameterClumpTemplate(species[s].clump_shape, &shapes[s], &why)) {
      if (error) *error = "field 'species[" + std::to_string(s) + "].clump': " + why;
      return false;
    }
  }
  return true;
}

double ParticleSystem::EnclosingRadius(int species, double d) const {
  return IsClump(species) ? shapes[species].BoundingRadius() * d : 0.5 * d;
}

void ParticleSystem::Add(int species, int material, double density, double d, const Vec3& x,
                         const Vec3& v, const Vec3& omega, const Quaternion& q) {
  if (!IsClump(species)) {
    spheres.Add(next_id++, species, material, 0.5 * d, density, x, v, omega);
    return;
  }
  const int64_t clump_id = next_id++;  // members take the ids after it
  const size_t c = clumps.Add(clump_id, species, material, shapes[species], d, density, x, q, v,
                              spheres, next_id);
  clumps.rotation[c] = StateFromAngularVelocity(q, omega, clumps.principal_inertia_kg_m2[c]);
  clumps.UpdateMembers(c, spheres);
}

double ParticleSystem::KineticEnergySince(size_t first_sphere, size_t first_clump) const {
  double e = 0;
  for (size_t i = first_sphere; i < spheres.Size(); ++i) e += spheres.FreeKineticEnergy(i);
  for (size_t c = first_clump; c < clumps.Size(); ++c) e += clumps.KineticEnergy(c);
  return e;
}

double ParticleSystem::KineticEnergy() const { return KineticEnergySince(0, 0); }

double ParticleSystem::GravitationalPotential(const Vec3& g) const {
  return ReleasableGravitationalEnergy(g, {});  // −Σ m g·x = Σ m g·(0 − x)
}

double ParticleSystem::ReleasableGravitationalEnergy(const Vec3& g, const Vec3& lowest,
                                                     size_t first_sphere,
                                                     size_t first_clump) const {
  double e = 0;
  for (size_t i = first_sphere; i < spheres.Size(); ++i)
    if (spheres.body[i] < 0) e += spheres.mass_kg[i] * Dot(g, lowest - spheres.position_m[i]);
  for (size_t c = first_clump; c < clumps.Size(); ++c)
    e += clumps.mass_kg[c] * Dot(g, lowest - clumps.position_m[c]);
  return e;
}

size_t ParticleSystem::BodyCount() const {
  return spheres.Size() - clumps.member_slot.size() + clumps.Size();
}

namespace {
// Half kicks of free spheres [0, n): one (finish = false) or two (the deferred one first).
template <bool kFinish, bool kDrift>
void KickSpheres(Particles& p, size_t n, double dt) {
  const double half = 0.5 * dt;
  tbb::parallel_for(tbb::blocked_range<size_t>(0, n, 1024), [&](const auto& range) {
    for (size_t i = range.begin(); i != range.end(); ++i) {
      if (p.body[i] >= 0) continue;  // clump members move with their clump
      const Vec3 dv = p.force_N[i] * (half * p.inv_mass[i]);
      const Vec3 dw = p.torque_N_m[i] * (half * p.inv_inertia[i]);
      Vec3 v = p.velocity_m_s[i], w = p.angular_velocity_rad_s[i];
      if constexpr (kFinish) v += dv, w += dw;
      v += dv, w += dw;
      p.velocity_m_s[i] = v;
      p.angular_velocity_rad_s[i] = w;
      if constexpr (kDrift) p.position_m[i] += v * dt;
    }
  }, tbb::static_partitioner());
}
}  // namespace

void ParticleSystem::FinishKick(double dt, size_t moving_spheres) {
  KickSpheres<false, false>(spheres, std::min(moving_spheres, spheres.Size()), dt);
}

void ParticleSystem::KickDrift(double dt, size_t moving_spheres, bool finish_last_kick) {
  const double half = 0.5 * dt;
  Particles& p = spheres;
  const size_t n = std::min(moving_spheres, p.Size());
  if (finish_last_kick) KickSpheres<true, true>(p, n, dt);
  else KickSpheres<false, true>(p, n, dt);
  Clumps& c = clumps;
  // The drift (Drift's midpoint scheme) in passes over blocks of clumps, and the members in a
  // pass of their own: short loop bodies let the processor overlap successive clumps' long
  // dependency chains (the rotations), which one long body would serialise.
  constexpr size_t kBlock = 64;
  tbb::parallel_for(tbb::blocked_range<size_t>(0, c.Size(), 256), [&](const auto& range) {
    std::array<Quaternion, kBlock> half_turned;
    std::array<Vec3, kBlock> inverse_inertia;
    for (size_t b = range.begin(); b < range.end(); b += kBlock) {
      const size_t e = std::min(b + kBlock, range.end());
      for (size_t k = b; k != e; ++k) {
        c.velocity_m_s[k] += c.force_N[k] * (half / c.mass_kg[k]);
        HalfKick(c.rotation[k], c.torque_N_m[k], dt);
        c.position_m[k] += c.velocity_m_s[k] * dt;
        inverse_inertia[k - b] = rigid_detail::Reciprocal(c.principal_inertia_kg_m2[k]);
        half_turned[k - b] = rigid_detail::MidpointHalfTurn(c.rotation[k], inverse_inertia[k - b], dt);
      }
      for (size_t k = b; k != e; ++k)
        c.rotation[k].orientation = rigid_detail::MidpointFullTurn(
            c.rotation[k], half_turned[k - b], inverse_inertia[k - b], dt);
    }
    for (size_t k = range.begin(); k != range.end(); ++k) c.UpdateMembers(k, p);
  });
}

void ParticleSystem::ReduceAndKick(const Vec3& gravity, double dt, size_t moving_spheres,
                                   bool defer_sphere_kick) {
  const double half = 0.5 * dt;
  Particles& p = spheres;
  if (!defer_sphere_kick) FinishKick(dt, moving_spheres);
  Clumps& c = clumps;
  tbb::parallel_for(tbb::blocked_range<size_t>(0, c.Size(), 256), [&](const auto& range) {
    for (size_t k = range.begin(); k != range.end(); ++k) {
      c.ReduceForces(k, p, gravity);
      c.velocity_m_s[k] += c.force_N[k] * (half / c.mass_kg[k]);
      HalfKick(c.rotation[k], c.torque_N_m[k], dt);
      c.UpdateMemberVelocities(k, p);  // at the full step, for outputs and energies
    }
  });
}

void ParticleSystem::WrapPeriodic(const PeriodicBox& box) {
  Particles& p = spheres;
  tbb::parallel_for(tbb::blocked_range<size_t>(0, p.Size(), 1024), [&](const auto& range) {
    for (size_t i = range.begin(); i != range.end(); ++i)
      if (p.body[i] < 0) p.position_m[i] = box.Wrap(p.position_m[i]);
  });
  tbb::parallel_for(tbb::blocked_range<size_t>(0, clumps.Size(), 256), [&](const auto& range) {
    for (size_t k = range.begin(); k != range.end(); ++k) {
      const Vec3 wrapped = box.Wrap(clumps.position_m[k]);
      if (wrapped == clumps.position_m[k]) continue;
      clumps.position_m[k] = wrapped;
      clumps.UpdateMembers(k, p);
    }
  });
}

void ParticleSystem::ReduceClumpForces(const Vec3& gravity) {
  tbb::parallel_for(tbb::blocked_range<size_t>(0, clumps.Size(), 256), [&](const auto& range) {
    for (size_t k = range.begin(); k != range.end(); ++k) clumps.ReduceForces(k, spheres, gravity);
  });
}

std::vector<uint32_t> ParticleSystem::GroupClumpMembers(const std::vector<uint32_t>& order) const {
  if (clumps.Size() == 0) return order;
  std::vector<uint8_t> placed(clumps.Size(), 0);
  std::vector<uint32_t> grouped;
  grouped.reserve(order.size());
  for (uint32_t s : order) {
    const int c = spheres.body[s];
    if (c < 0) {
      grouped.push_back(s);
    } else if (!placed[c]) {
      placed[c] = 1;
      for (uint32_t k = clumps.member_start[c]; k < clumps.member_start[c + 1]; ++k)
        grouped.push_back(clumps.member_slot[k]);
    }
  }
  return grouped;
}

void ParticleSystem::Permute(const std::vector<uint32_t>& order) {
  if (order.empty()) return;
  spheres.Permute(order);
  clumps.RemapSlots(order);
  // Clumps in the order of their first member's slot, so the clump loops walk the sphere
  // arrays forwards (with GroupClumpMembers: contiguously).
  std::vector<uint32_t> by_slot(clumps.Size());
  std::iota(by_slot.begin(), by_slot.end(), 0u);
  auto first_slot = [&](uint32_t c) { return clumps.member_slot[clumps.member_start[c]]; };
  auto earlier = [&](uint32_t a, uint32_t b) { return first_slot(a) < first_slot(b); };
  if (std::is_sorted(by_slot.begin(), by_slot.end(), earlier)) return;
  std::sort(by_slot.begin(), by_slot.end(), earlier);
  clumps.Select(by_slot);
  for (size_t c = 0; c < clumps.Size(); ++c)
    for (uint32_t k = clumps.member_start[c]; k < clumps.member_start[c + 1]; ++k)
      spheres.body[clumps.member_slot[k]] = static_cast<int>(c);
}

std::vector<uint32_t> ParticleSystem::Remove(const std::vector<uint8_t>& sphere_gone,
                                            const std::vector<uint8_t>& clump_gone) {
  std::vector<uint32_t> order;
  order.reserve(spheres.Size());
  for (uint32_t s = 0; s < spheres.Size(); ++s) {
    const int c = spheres.body[s];
    if (!(c < 0 ? sphere_gone[s] : clump_gone[c])) order.push_back(s);
  }
  if (order.size() == spheres.Size()) return order;
  spheres.Permute(order);  // shorter order: the removed slots are dropped
  const std::vector<int> new_clump = clumps.Keep(clump_gone, order);
  for (int& c : spheres.body)
    if (c >= 0) c = new_clump[c];
  return order;
}

Quaternion UniformRandomOrientation(double u1, double u2, double u3) {
  const double a = std::sqrt(1 - u1), b = std::sqrt(u1);
  const double t1 = 2 * std::numbers::pi * u2, t2 = 2 * std::numbers::pi * u3;
  return Normalized(Quaternion{b * std::cos(t2), a * std::sin(t1), a * std::cos(t1), b * std::sin(t2)});
}

}  // namespace demcal::core
