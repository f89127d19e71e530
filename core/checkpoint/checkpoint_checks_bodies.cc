// The restored-state checks of a checkpoint, part 1: particles, clumps, time and factories.
// Every count and index is checked against the scene before the engine uses it (a damaged
// index would otherwise be a memory error in the force loop), and every value that enters the
// next step is checked finite and in range. A failure names the array, the slot and the bound.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <sstream>

#include "core/simulation/simulation.h"

namespace demcal::core {
namespace {

bool Finite(double x) { return std::isfinite(x); }
bool Finite(const Vec3& v) { return IsFinite(v); }
bool Finite(const Quaternion& q) {
  return std::isfinite(q.w) && std::isfinite(q.x) && std::isfinite(q.y) && std::isfinite(q.z);
}

template <class... Vectors>
bool SameSize(size_t n, const Vectors&... v) {
  return ((v.size() == n) && ...);
}

bool Fail(const std::string& why, std::string* error) {
  *error = why;
  return false;
}

// Ids must be in [0, next_id) and unique over spheres and clumps.
bool CheckIds(const ParticleSystem& s, std::string* error) {
  std::vector<int64_t> ids(s.spheres.id);
  ids.insert(ids.end(), s.clumps.id.begin(), s.clumps.id.end());
  for (int64_t id : ids)
    if (id < 0 || id >= s.next_id)
      return Fail("particles: id " + std::to_string(id) + " outside [0, next id " +
                      std::to_string(s.next_id) + ")",
                  error);
  std::sort(ids.begin(), ids.end());
  const auto twice = std::adjacent_find(ids.begin(), ids.end());
  if (twice != ids.end()) return Fail("particles: id " + std::to_string(*twice) + " appears twice", error);
  return true;
}

}  // namespace

bool Simulation::CheckRestoredBodies(std::string* error) const {
  const Particles& p = system_.spheres;
  const Clumps& c = system_.clumps;
  const size_t n = p.position_m.size(), clumps = c.position_m.size();
  if (n >= UINT32_MAX) return Fail("particles: " + std::to_string(n) + " slots", error);
  if (!SameSize(n, p.velocity_m_s, p.angular_velocity_rad_s, p.force_N, p.torque_N_m, p.radius_m,
                p.mass_kg, p.inv_mass, p.inv_inertia, p.species, p.material, p.body, p.id))
    return Fail("particles: the per-particle arrays differ in length", error);
  const int species = static_cast<int>(scene_.species.size());
  // Largest sphere of each species: half its largest diameter (its size distribution's, or an
  // explicit particle's), or for a clump species its largest member at that size.
  std::vector<double> max_diameter(species), max_radius(species);
  for (int k = 0; k < species; ++k) max_diameter[k] = scene_.species[k].size.MaxDiameter();
  for (const ParticleSpec& q : scene_.particles)
    max_diameter[q.species] = std::max(max_diameter[q.species], q.diameter_m);
  for (int k = 0; k < species; ++k) {
    const double d = max_diameter[k];
    max_radius[k] = 0.5 * d;
    if (system_.IsClump(k)) {
      max_radius[k] = 0;
      for (const ClumpSphere& m : system_.shapes[k].spheres)
        max_radius[k] = std::max(max_radius[k], m.radius_m * d);
    }
    max_radius[k] *= 1 + 1e-9;
  }
  for (size_t i = 0; i < n; ++i) {
    std::ostringstream at;
    at << "particles: slot " << i << " (id " << p.id[i] << "): ";
    if (p.species[i] < 0 || p.species[i] >= species)
      return Fail(at.str() + "species index " + std::to_string(p.species[i]) + " (the scene has " +
                      std::to_string(species) + ")",
                  error);
    if (p.material[i] != scene_.species[p.species[i]].material)
      return Fail(at.str() + "material index " + std::to_string(p.material[i]) +
                      " is not its species' material",
                  error);
    if (!(p.radius_m[i] > 0 && p.radius_m[i] <= max_radius[p.species[i]])) {
      at << "radius " << p.radius_m[i] << " m outside (0, " << max_radius[p.species[i]]
         << "] m of its species";
      return Fail(at.str(), error);
    }
    if (!(p.mass_kg[i] > 0 && Finite(p.mass_kg[i]) && p.inv_mass[i] >= 0 && Finite(p.inv_mass[i]) &&
          p.inv_inertia[i] >= 0 && Finite(p.inv_inertia[i])))
      return Fail(at.str() + "mass or inverse mass or inertia not positive and finite", error);
    if (!Finite(p.position_m[i]) || !Finite(p.velocity_m_s[i]) ||
        !Finite(p.angular_velocity_rad_s[i]) || !Finite(p.force_N[i]) || !Finite(p.torque_N_m[i]))
      return Fail(at.str() + "non-finite position, velocity, spin, force or torque", error);
    if (p.body[i] < -1 || p.body[i] >= static_cast<int64_t>(clumps))
      return Fail(at.str() + "clump index " + std::to_string(p.body[i]) + " (there are " +
                      std::to_string(clumps) + " clumps)",
                  error);
  }
  if (!SameSize(clumps, c.velocity_m_s, c.rotation, c.principal_inertia_kg_m2, c.mass_kg, c.force_N,
                c.torque_N_m, c.species, c.id) ||
      c.member_start.size() != clumps + 1 || c.member_offset_m.size() != c.member_slot.size() ||
      c.member_start.front() != 0 || c.member_start.back() != c.member_slot.size())
    return Fail("clumps: the per-clump arrays or the member rows differ in length", error);
  std::vector<uint8_t> member(n, 0);
  for (size_t k = 0; k < clumps; ++k) {
    const std::string at = "clumps: clump " + std::to_string(k) + ": ";
    if (c.member_start[k] > c.member_start[k + 1])
      return Fail(at + "member rows out of order", error);
    if (c.species[k] < 0 || c.species[k] >= species || !system_.IsClump(c.species[k]))
      return Fail(at + "species index " + std::to_string(c.species[k]) + " is not a clump species",
                  error);
    const size_t members = c.member_start[k + 1] - c.member_start[k];
    if (members != system_.shapes[c.species[k]].spheres.size())
      return Fail(at + std::to_string(members) + " members, its shape has " +
                      std::to_string(system_.shapes[c.species[k]].spheres.size()),
                  error);
    const Vec3& inertia = c.principal_inertia_kg_m2[k];
    const Quaternion& q = c.rotation[k].orientation;
    if (!(c.mass_kg[k] > 0 && Finite(c.mass_kg[k]) && inertia.x > 0 && inertia.y > 0 &&
          inertia.z > 0 && Finite(inertia)))
      return Fail(at + "mass or inertia not positive and finite", error);
    if (!Finite(c.position_m[k]) || !Finite(c.velocity_m_s[k]) || !Finite(c.force_N[k]) ||
        !Finite(c.torque_N_m[k]) || !Finite(q) || !Finite(c.rotation[k].angular_momentum_kg_m2_s) ||
        std::abs(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z - 1) > 1e-6)
      return Fail(at + "non-finite state or an orientation that is not a unit quaternion", error);
    for (uint32_t m = c.member_start[k]; m < c.member_start[k + 1]; ++m) {
      const uint32_t slot = c.member_slot[m];
      if (slot >= n || p.body[slot] != static_cast<int>(k) || member[slot] ||
          !Finite(c.member_offset_m[m]))
        return Fail(at + "member slot " + std::to_string(slot) +
                        " is not a sphere of this clump (or listed twice)",
                    error);
      member[slot] = 1;
    }
  }
  for (size_t i = 0; i < n; ++i)
    if (p.body[i] >= 0 && !member[i])
      return Fail("particles: slot " + std::to_string(i) + " names clump " +
                      std::to_string(p.body[i]) + " but is not among its members",
                  error);
  return CheckIds(system_, error);
}

bool Simulation::CheckRestoredProgress(std::string* error) const {
  if (!(std::isfinite(time_s_) && time_s_ >= 0))
    return Fail("time " + std::to_string(time_s_) + " s is not finite and >= 0", error);
  // time_s_ is a sum of Δt, one per step: it must agree with steps × Δt up to rounding.
  const double expected = static_cast<double>(steps_) * dt_;
  if (steps_ < 0 || std::abs(time_s_ - expected) > 1e-6 * expected + dt_) {
    std::ostringstream os;
    os << "step count " << steps_ << " does not match the time " << time_s_ << " s at time step "
       << dt_ << " s";
    return Fail(os.str(), error);
  }
  if (!std::isfinite(energy_budget_J_) || !(std::isfinite(energy_scale_J_) && energy_scale_J_ >= 0))
    return Fail("energy budget not finite", error);
  // The sink pass runs every sink_every_steps steps counted from the last one: a step ahead of
  // the step counter would postpone every later pass.
  if (last_sink_pass_step_ < 0 || last_sink_pass_step_ > steps_)
    return Fail("last sink pass at step " + std::to_string(last_sink_pass_step_) +
                    ", outside [0, " + std::to_string(steps_) + "]",
                error);
  for (const SinkReport& r : sink_reports_) {
    bool ok = r.particles.size() == scene_.species.size() && r.mass_kg.size() == scene_.species.size() &&
              (r.last_removal_s == -1 || (r.last_removal_s >= 0 && r.last_removal_s <= time_s_));
    for (size_t k = 0; ok && k < r.particles.size(); ++k)
      ok = r.particles[k] >= 0 && std::isfinite(r.mass_kg[k]) && r.mass_kg[k] >= 0;
    if (!ok)
      return Fail("sink '" + r.name + "': removed counts or masses are not one non-negative "
                  "value per species, or its last removal is not within the run",
                  error);
  }
  for (size_t f = 0; f < factories_.size(); ++f) {
    std::string why;
    if (!factories_[f].CheckRestored(time_s_, system_, &why))
      return Fail("factories[" + std::to_string(f) + "] '" + factories_[f].spec().name + "': " + why,
                  error);
  }
  return true;
}

bool ParticleFactory::CheckRestored(double time_s, const ParticleSystem& system,
                                    std::string* error) const {
  const FactoryReport& r = report_;
  if (!(std::isfinite(r.inserted_mass_kg) && std::isfinite(r.requested_mass_kg) &&
        std::isfinite(r.active_time_s) && std::isfinite(owed_kg_) && r.particles >= 0 &&
        r.full_batches >= 0 && r.inserted_mass_kg >= 0 && r.requested_mass_kg >= 0 &&
        r.active_time_s >= 0 && owed_kg_ <= r.requested_mass_kg * (1 + 1e-9) + 1e-300))
    return Fail("inserted, requested or owed mass, active time or counts out of range", error);
  // The region rises only after the heap, and only for a factory that follows it; a NaN or far
  // lift would put the insertion region (and its occupancy grid) nowhere. 1e6 m: the coordinate
  // bound of the scene's geometry (mesh vertices, scene_limits).
  const double lift = r.region_lift_m;
  if (!(std::isfinite(lift) && lift >= 0 && lift <= 1e6) ||
      (lift > 0 && !(spec_.follow_heap_clearance_m > 0))) {
    std::ostringstream os;
    os << "region lift " << lift << " m outside [0, 1e+06] m, or set on a factory that does not "
       << "follow the heap";
    return Fail(os.str(), error);
  }
  // Batches are due every interval from start_s on, and all those due by now were inserted.
  const double latest = std::max(spec_.start_s, time_s) + interval_;
  if (!(next_batch_s_ >= spec_.start_s && next_batch_s_ <= latest + 1e-9 * std::abs(latest))) {
    std::ostringstream os;
    os << "next batch time " << next_batch_s_ << " s outside [" << spec_.start_s << ", " << latest
       << "] s";
    return Fail(os.str(), error);
  }
  // Carried draws: species of the mixture, sizes of its distribution (a damaged index would read
  // past the mixture), and no more than the batches drew: drawing stops once what is carried
  // and new reaches what is owed, so the carry weighs at most the owed mass plus one body.
  double heaviest_kg = 0;
  for (const SpeciesDraw& m : mixture_)
    heaviest_kg = std::max(heaviest_kg, DrawMassKg(system, m, m.size->MaxDiameter()));
  for (size_t k = 0; k < carried_.size(); ++k) {
    const CarriedDraw& c = carried_[k];
    const bool species_ok = c.mixture_index >= 0 && c.mixture_index < std::ssize(mixture_);
    const SizeDistribution* size = species_ok ? mixture_[c.mixture_index].size : nullptr;
    if (!species_ok || !(c.diameter_m >= size->MinDiameter() * (1 - 1e-12) &&
                         c.diameter_m <= size->MaxDiameter() * (1 + 1e-12))) {
      std::ostringstream os;
      os << "carried draw " << k << ": mixture index " << c.mixture_index << " (of "
         << mixture_.size() << ") or diameter " << c.diameter_m << " m not of its species";
      return Fail(os.str(), error);
    }
  }
  const double carried_kg = CarriedMassKg(system);
  if (carried_kg > (std::max(owed_kg_, 0.0) + heaviest_kg) * (1 + 1e-9)) {
    std::ostringstream os;
    os << carried_.size() << " carried draws weigh " << carried_kg << " kg, more than the "
       << owed_kg_ << " kg owed plus one body (" << heaviest_kg << " kg)";
    return Fail(os.str(), error);
  }
  return true;
}

}  // namespace demcal::core
