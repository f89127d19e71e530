// The restored-state checks of a checkpoint, part 3: physical consistency. Parts 1 and 2 check
// that every value is finite and every index in range; a hand edit behind a valid checksum can
// still leave a state no run produces (a mass that does not belong to its radius, a clump centre
// away from its spheres, an energy budget that switches the blow-up check off, counters that
// count particles that never existed). What the scene determines is recomputed here and
// compared. A failure names the check.
//
// Tolerances. Masses, inertias and member offsets are recomputed by the same formulas the engine
// used (Particles::Add, Clumps::Add), from stored values, in at most a few operations each
// rounded to 2^-53 ≈ 1.1e-16 relative: they agree to ~1e-15. kRoundOff = 1e-12 leaves three
// decades for a compiler's different contraction (FMA) of the same formula and is nine decades
// below any edit that changes the physics. Sums over the run (inserted and removed masses, the
// energy budget) accumulate one rounding per term and get kSumRoundOff = 1e-9.
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>

#include "core/simulation/simulation.h"

namespace demcal::core {
namespace {

constexpr double kRoundOff = 1e-12;
constexpr double kSumRoundOff = 1e-9;

bool Fail(const std::string& why, std::string* error) {
  *error = why;
  return false;
}

// |a − b| within `tolerance` of the larger magnitude.
bool Close(double a, double b, double tolerance = kRoundOff) {
  return std::abs(a - b) <= tolerance * std::max(std::abs(a), std::abs(b));
}

bool Close(const Vec3& a, const Vec3& b, double scale) {
  return Norm(a - b) <= kRoundOff * scale;
}

double SphereMass(double density, double radius) {
  return density * 4.0 / 3.0 * std::numbers::pi * radius * radius * radius;
}

std::string Slot(size_t i, int64_t id) {
  return "particles: slot " + std::to_string(i) + " (id " + std::to_string(id) + "): ";
}

}  // namespace

bool Simulation::CheckRestoredPhysics(std::string* error) const {
  const Particles& p = system_.spheres;
  const Clumps& c = system_.clumps;
  for (size_t i = 0; i < p.Size(); ++i) {
    if (p.body[i] >= 0) continue;  // a clump member: checked with its clump below
    const double density = scene_.materials[p.material[i]].density_kg_m3;
    const double mass = SphereMass(density, p.radius_m[i]);
    const bool fixed = p.inv_mass[i] == 0;
    const double inertia = 0.4 * mass * p.radius_m[i] * p.radius_m[i];
    if (!Close(p.mass_kg[i], mass) ||
        (fixed ? p.inv_inertia[i] != 0
               : !Close(p.inv_mass[i], 1.0 / mass) || !Close(p.inv_inertia[i], 1.0 / inertia))) {
      std::ostringstream os;
      os << Slot(i, p.id[i]) << "mass " << p.mass_kg[i] << " kg (inverse " << p.inv_mass[i]
         << ", inverse inertia " << p.inv_inertia[i] << ") is not that of a sphere of radius "
         << p.radius_m[i] << " m and density " << density << " kg/m3 (" << mass
         << " kg); mass or inertia edited without the radius?";
      return Fail(os.str(), error);
    }
  }
  for (size_t k = 0; k < c.Size(); ++k) {
    const ClumpTemplate& shape = system_.shapes[c.species[k]];
    const uint32_t first = c.member_start[k];
    // The body's diameter d is not stored: every member radius is the template's times d.
    const double d = p.radius_m[c.member_slot[first]] / shape.spheres[0].radius_m;
    const double density = scene_.materials[scene_.species[c.species[k]].material].density_kg_m3;
    const std::string at =
        "clumps: clump " + std::to_string(k) + " (id " + std::to_string(c.id[k]) + "): ";
    const double d3 = density * d * d * d;
    if (!Close(c.mass_kg[k], shape.mass_kg * d3) ||
        !Close(c.principal_inertia_kg_m2[k].x, shape.principal_inertia_kg_m2.x * d3 * d * d) ||
        !Close(c.principal_inertia_kg_m2[k].y, shape.principal_inertia_kg_m2.y * d3 * d * d) ||
        !Close(c.principal_inertia_kg_m2[k].z, shape.principal_inertia_kg_m2.z * d3 * d * d)) {
      std::ostringstream os;
      os << at << "mass " << c.mass_kg[k] << " kg or inertia is not that of its shape at the "
         << "size of its spheres (" << shape.mass_kg * d3 << " kg); edited without the radii?";
      return Fail(os.str(), error);
    }
    // The template's centre of mass is its origin, so the members' positions must be the clump
    // centre plus their rotated offsets: then the centre is the members' centre of mass.
    const Quaternion& q = c.rotation[k].orientation;
    for (uint32_t m = first; m < c.member_start[k + 1]; ++m) {
      const ClumpSphere& s = shape.spheres[m - first];
      const uint32_t slot = c.member_slot[m];
      // A member carries its clump's mass for contacts and is never integrated itself.
      if (p.mass_kg[slot] != c.mass_kg[k] || p.inv_mass[slot] != 0 || p.inv_inertia[slot] != 0)
        return Fail(Slot(slot, p.id[slot]) + "a clump member whose mass is not its clump's " +
                        "(or that has an inverse mass or inertia of its own)",
                    error);
      const Vec3 offset = s.centre_m * d;
      const Vec3 expected = c.position_m[k] + Rotate(q, c.member_offset_m[m]);
      const double scale = Norm(c.position_m[k]) + Norm(offset) + d;
      if (!Close(p.radius_m[slot], s.radius_m * d) || !Close(c.member_offset_m[m], offset, d) ||
          !Close(p.position_m[slot], expected, scale)) {
        std::ostringstream os;
        os << at << "member " << m - first << " (slot " << slot << ") is "
           << Norm(p.position_m[slot] - expected) << " m from where its shape puts it about the "
           << "clump centre (or its radius or offset is not its shape's at the clump's size); "
           << "the centre is not its members' centre of mass";
        return Fail(os.str(), error);
      }
    }
  }
  return CheckRestoredEnergy(error) && CheckRestoredCounters(error);
}

double Simulation::InsertedEnergyBound(double adhesion_per_sphere_J) const {
  double mass = 0, speed = 0, spheres = 1;
  for (int k = 0; k < static_cast<int>(scene_.species.size()); ++k) {
    double lo = 0, hi = 0;
    BodyMassRange(k, &lo, &hi);
    mass = std::max(mass, hi);
    spheres = std::max(spheres, static_cast<double>(system_.shapes[k].spheres.size()));
  }
  for (const FactorySpec& f : scene_.factories) speed = std::max(speed, Norm(f.velocity_m_s));
  const double fall = Norm(scene_.domain_max_m - scene_.domain_min_m);  // the domain's diagonal
  return mass * (0.5 * speed * speed + Norm(scene_.gravity_m_s2) * fall) +
         spheres * adhesion_per_sphere_J;
}

void Simulation::BodyMassRange(int k, double* lo_kg, double* hi_kg) const {
  const Species& sp = scene_.species[k];
  double d_lo = sp.size.MinDiameter(), d_hi = sp.size.MaxDiameter();
  for (const ParticleSpec& q : scene_.particles)
    if (q.species == k && q.diameter_m > 0)
      d_lo = std::min(d_lo, q.diameter_m), d_hi = std::max(d_hi, q.diameter_m);
  const double density = scene_.materials[sp.material].density_kg_m3;
  // Mass per d³: a sphere's ρπ/6, a clump template's (unit diameter and density) mass × ρ.
  const double per_d3 = system_.IsClump(k) ? system_.shapes[k].mass_kg * density
                                           : density * std::numbers::pi / 6;
  *lo_kg = per_d3 * d_lo * d_lo * d_lo;
  *hi_kg = per_d3 * d_hi * d_hi * d_hi;
}

bool Simulation::CheckRestoredEnergy(std::string* error) const {
  // The scale only grows by what enters: the initial state's, each inserted body's at most
  // inserted_energy_bound_J_, and the work of moving walls (not bounded from the scene alone).
  double inserted = 0;  // each count checked >= 0; a double sum cannot overflow
  for (const ParticleFactory& f : factories_) inserted += static_cast<double>(f.report().particles);
  const double most = (initial_energy_scale_J_ +
                       inserted * inserted_energy_bound_J_) *
                      (1 + kSumRoundOff);
  if (!walls_move_ && energy_scale_J_ > most) {
    std::ostringstream os;
    os << "energy scale " << energy_scale_J_ << " J exceeds what the scene's initial state and "
       << inserted << " inserted bodies can release (" << most << " J)";
    return Fail(os.str(), error);
  }
  // The budget is the mechanical energy the run has been given; the energy now differs from it
  // by what was dissipated or released, each at most the scale (the run's blow-up check allows
  // half of it upwards).
  const double energy =
      system_.KineticEnergy() + system_.GravitationalPotential(scene_.gravity_m_s2);
  const double gap = std::abs(energy - energy_budget_J_);
  if (gap > energy_scale_J_ + kSumRoundOff * (std::abs(energy) + std::abs(energy_budget_J_)) +
                1e-30) {
    std::ostringstream os;
    os << "energy budget " << energy_budget_J_ << " J is " << gap << " J from the mechanical "
       << "energy of the restored particles (" << energy << " J), more than the energy scale "
       << energy_scale_J_ << " J allows";
    return Fail(os.str(), error);
  }
  return true;
}

bool Simulation::CheckRestoredCounters(std::string* error) const {
  // Bodies are conserved: every body the scene placed or a factory inserted is still there or
  // was counted by a sink.
  // Sums as doubles: exact to 2^53 bodies, and an absurd count cannot overflow them.
  double inserted = 0, removed = 0;
  const int species = static_cast<int>(scene_.species.size());
  for (size_t f = 0; f < factories_.size(); ++f) {
    const FactoryReport& r = factories_[f].report();
    inserted += static_cast<double>(r.particles);
    double lo = std::numeric_limits<double>::infinity(), hi = 0;
    for (int k : factories_[f].spec().species) {
      double a = 0, b = 0;
      BodyMassRange(k, &a, &b);
      lo = std::min(lo, a), hi = std::max(hi, b);
    }
    const double n = static_cast<double>(r.particles);
    if (r.inserted_mass_kg < n * lo * (1 - kSumRoundOff) ||
        r.inserted_mass_kg > n * hi * (1 + kSumRoundOff)) {
      std::ostringstream os;
      os << "factories[" << f << "] '" << r.name << "': " << r.particles << " inserted bodies "
         << "cannot weigh " << r.inserted_mass_kg << " kg (each " << lo << " to " << hi << " kg)";
      return Fail(os.str(), error);
    }
  }
  for (const SinkReport& r : sink_reports_)
    for (int k = 0; k < species; ++k) {
      double lo = 0, hi = 0;
      BodyMassRange(k, &lo, &hi);
      const double n = static_cast<double>(r.particles[k]);
      removed += static_cast<double>(r.particles[k]);
      if (r.mass_kg[k] < n * lo * (1 - kSumRoundOff) ||
          r.mass_kg[k] > n * hi * (1 + kSumRoundOff)) {
        std::ostringstream os;
        os << "sink '" << r.name << "': " << r.particles[k] << " removed bodies of species '"
           << scene_.species[k].name << "' cannot weigh " << r.mass_kg[k] << " kg (each " << lo
           << " to " << hi << " kg)";
        return Fail(os.str(), error);
      }
    }
  const double now = static_cast<double>(system_.BodyCount());
  const double placed = static_cast<double>(initial_bodies_);
  if (placed + inserted != now + removed) {
    std::ostringstream os;
    os << "counters: " << placed << " bodies placed at the start and " << inserted
       << " inserted by factories, but " << now << " present and " << removed
       << " removed by sinks";
    return Fail(os.str(), error);
  }
  return true;
}

}  // namespace demcal::core
