// Scene::IsValid: every field of a scene checked against its physical range, then the
// cross-field limits (walls inside the domain and not across a periodic axis: wall_validation.h;
// particles not inside one another, factories that fit, a run that fits a step counter).
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "core/contact/jkr.h"
#include "core/contact/normal_model.h"
#include "core/scene/field_checker.h"
#include "core/limits/physical_limits.h"
#include "core/scene/scene.h"
#include "core/scene/scene_overlaps.h"
#include "core/scene/wall_validation.h"

namespace demcal::core {
namespace {

using Checker = FieldChecker;


void CheckMaterials(const Scene& s, Checker& c) {
  if (s.materials.empty()) c.Fail("field 'materials' must list at least one material");
  for (size_t i = 0; i < s.materials.size(); ++i) {
    const Material& m = s.materials[i];
    const std::string f = IndexedField("materials", i);
    c.Within(f + ".youngs_modulus_Pa", m.youngs_modulus_Pa, limits::kYoungsModulus, "Pa");
    c.Within(f + ".poisson_ratio", m.poisson_ratio, limits::kPoissonRatio);
    // A wall material needs no density (0); a particle material's is checked with its species.
    c.Range(f + ".density_kg_m3", m.density_kg_m3, 0, limits::kParticleDensity.hi, false, false,
            "kg/m3");
  }
}

void CheckSpecies(const Scene& s, Checker& c) {
  for (size_t i = 0; i < s.species.size(); ++i) {
    const Species& sp = s.species[i];
    const std::string f = IndexedField("species", i);
    if (sp.material < 0 || sp.material >= static_cast<int>(s.materials.size()))
      c.Fail("field '" + f + ".material' names no defined material");
    else
      c.Within(f + ".material density", s.materials[sp.material].density_kg_m3,
               limits::kParticleDensity, "kg/m3");
    const SizeDistribution& d = sp.size;
    using K = SizeDistribution::Kind;
    if (d.kind == K::kFixed) c.Within(f + ".diameter_m", d.diameter_m, limits::kDiameter, "m");
    if (d.kind == K::kUniform) {
      c.Within(f + ".diameter_m.min", d.min_diameter_m, limits::kDiameter, "m");
      c.Range(f + ".diameter_m.max", d.max_diameter_m, d.min_diameter_m, limits::kDiameter.hi,
              false, false, "m");
    }
    if (d.kind == K::kTable) {
      if (d.table_diameter_m.empty() || d.table_diameter_m.size() != d.table_number_fraction.size())
        c.Fail("field '" + f + ".diameter_table' needs equally long non-empty diameter and fraction lists");
      double sum = 0;
      for (size_t k = 0; k < d.table_diameter_m.size(); ++k) {
        c.Within(f + ".diameter_table[" + std::to_string(k) + "].diameter_m",
                 d.table_diameter_m[k], limits::kDiameter, "m");
        c.Range(f + ".diameter_table[" + std::to_string(k) + "].number_fraction", d.table_number_fraction[k], 0, 1, false, false);
        sum += d.table_number_fraction[k];
      }
      if (std::abs(sum - 1.0) > 1e-6) c.Fail("field '" + f + ".diameter_table' number fractions must sum to 1");
    }
    for (size_t k = 0; k < sp.clump_shape.size(); ++k) {
      const std::string member = f + ".clump.spheres[" + std::to_string(k) + "]";
      c.Within(member + ".radius", sp.clump_shape[k].radius, limits::kClumpLength);
      for (int a = 0; a < 3; ++a)
        c.Range(member + ".centre[" + std::to_string(a) + "]", sp.clump_shape[k].centre[a],
                -limits::kClumpLength.hi, limits::kClumpLength.hi, false, false);
    }
  }
}

void CheckPairs(const Scene& s, Checker& c) {
  const size_t n = s.materials.size();
  if (s.pair_parameters.size() != n * n) {
    c.Fail("field 'interactions' must resolve to one entry per material pair");
    return;
  }
  for (size_t i = 0; i < n; ++i) {
    for (size_t j = 0; j < n; ++j) {
      const PairParameters& p = s.pair_parameters[i * n + j];
      const std::string f = "interactions[" + s.materials[i].name + "," + s.materials[j].name + "]";
      c.Within(f + ".sliding_friction", p.sliding_friction, limits::kFriction);
      c.Within(f + ".rolling_friction", p.rolling_friction, limits::kFriction);
      c.Within(f + ".restitution", p.restitution, limits::kRestitution);
      c.Within(f + ".interfacial_energy_J_m2", p.interfacial_energy_J_m2,
               limits::kInterfacialEnergy, "J/m2");
      c.Within(f + ".cohesion_energy_density_J_m3", p.cohesion_energy_density_J_m3,
               limits::kCohesionEnergyDensity, "J/m3");
    }
  }
  // One normal law runs a scene (normal_model.h): a table that calls for two is refused.
  const auto called = NormalLawsCalledFor(s.pair_parameters);
  if (called.size() > 1) {
    std::string laws;
    for (const auto& [name, k] : called)
      laws += (laws.empty() ? "" : " and ") + name + " (first at interactions[" +
              s.materials[k / n].name + "," + s.materials[k % n].name + "])";
    c.Fail("field 'interactions' calls for two normal laws, " + laws +
           "; a scene runs one: give every pair either interfacial_energy_J_m2 (JKR) or "
           "cohesion_energy_density_J_m3 (sjkr), not both kinds");
  }
}

void CheckGeometry(const Scene& s, Checker& c) {
  c.Point("domain.min_m", s.domain_min_m);
  c.Point("domain.max_m", s.domain_max_m);
  for (int a = 0; a < 3; ++a)
    if (!(s.domain_max_m[a] > s.domain_min_m[a]))
      c.Fail("field 'domain.max_m' must exceed 'domain.min_m' on every axis");
  for (size_t i = 0; i < s.walls.size(); ++i) CheckSceneWall(s, i, c);
  c.Magnitude("gravity_m_s2", s.gravity_m_s2, limits::kGravity, "m/s2");
  const char* axis_names[3] = {"x", "y", "z"};
  for (int a = 0; a < 3 && c.ok(); ++a) {
    if (!s.periodic[a]) continue;
    const std::string f = std::string("periodic.") + axis_names[a];
    if (s.gravity_m_s2[a] != 0)
      c.Fail("field '" + f + "': a periodic axis must be perpendicular to gravity (energy "
             "accounting and heaps need a floor)");
    // Three neighbour cells must fit, so that no pair meets through two images.
    const double cell = s.MaxDiameter() + NeighbourSkin(s);
    const double length = s.domain_max_m[a] - s.domain_min_m[a];
    if (length < 3 * cell) {
      std::ostringstream os;
      os << "field '" << f << "': the domain is " << length << " m long on this axis; periodic "
         << "boundaries need at least 3 × (largest diameter + skin) = " << 3 * cell << " m";
      c.Fail(os.str());
    }
  }
}

void CheckParticles(const Scene& s, Checker& c) {
  const int ns = static_cast<int>(s.species.size());
  for (size_t i = 0; i < s.particles.size(); ++i) {
    const ParticleSpec& p = s.particles[i];
    const std::string f = IndexedField("particles", i);
    if (p.species < 0 || p.species >= ns) c.Fail("field '" + f + ".species' names no defined species");
    if (p.diameter_m != 0) c.Within(f + ".diameter_m", p.diameter_m, limits::kDiameter, "m");
    for (int a = 0; a < 3; ++a)
      if (p.position_m[a] < s.domain_min_m[a] || p.position_m[a] > s.domain_max_m[a])
        c.Fail("field '" + f + ".position_m' lies outside the domain");
    c.Magnitude(f + ".velocity_m_s", p.velocity_m_s, limits::kSpeed, "m/s");
    c.Magnitude(f + ".angular_velocity_rad_s", p.angular_velocity_rad_s, limits::kAngularSpeed,
                "rad/s");
    if (p.fixed && p.species >= 0 && p.species < ns && !s.species[p.species].clump_shape.empty())
      c.Fail("field '" + f + ".fixed': only spheres can be fixed, species '" +
             s.species[p.species].name + "' is a clump");
  }
  if (c.ok()) {
    const std::string overlap = ExplicitOverlapError(s);
    if (!overlap.empty()) c.Fail(overlap);
  }
  for (size_t i = 0; i < s.fills.size(); ++i) {
    const FillSpec& fl = s.fills[i];
    const std::string f = IndexedField("fills", i);
    if (fl.species < 0 || fl.species >= ns) c.Fail("field '" + f + ".species' names no defined species");
    c.Range(f + ".count", static_cast<double>(fl.count), 0, 1e8, true, false);
    c.Magnitude(f + ".velocity_m_s", fl.velocity_m_s, limits::kSpeed, "m/s");
    for (int a = 0; a < 3; ++a) {
      if (!(fl.region.max_m[a] > fl.region.min_m[a]))
        c.Fail("field '" + f + ".region' must be non-empty on every axis");
      if (fl.region.min_m[a] < s.domain_min_m[a] || fl.region.max_m[a] > s.domain_max_m[a])
        c.Fail("field '" + f + ".region' must lie inside the domain");
    }
  }
}

void CheckFactories(const Scene& s, Checker& c) {
  const int ns = static_cast<int>(s.species.size());
  for (size_t i = 0; i < s.factories.size(); ++i) {
    const FactorySpec& f = s.factories[i];
    const std::string name = IndexedField("factories", i);
    if (f.species.empty() || f.species.size() != f.mass_fractions.size()) {
      c.Fail("field '" + name + ".species' must list at least one species with a mass fraction each");
      continue;
    }
    double sum = 0, mean_density = 0, d_max = 0;
    for (size_t k = 0; k < f.species.size(); ++k) {
      const std::string fk = name + ".species[" + std::to_string(k) + "]";
      if (f.species[k] < 0 || f.species[k] >= ns) {
        c.Fail("field '" + fk + "' names no defined species");
        return;
      }
      c.Range(fk + ".mass_fraction", f.mass_fractions[k], 0, 1, false, false);
      sum += f.mass_fractions[k];
      const Species& sp = s.species[f.species[k]];
      mean_density += f.mass_fractions[k] * s.materials[sp.material].density_kg_m3;
      d_max = std::max(d_max, sp.size.MaxDiameter());
    }
    if (std::abs(sum - 1) > 1e-6) c.Fail("field '" + name + ".species' mass fractions must sum to 1");
    c.Within(name + ".mass_rate_kg_s", f.mass_rate_kg_s, limits::kMassRate, "kg/s");
    c.Range(name + ".start_s", f.start_s, 0, 1e9, false, false, "s");
    if (!std::isinf(f.end_s)) c.Range(name + ".end_s", f.end_s, f.start_s, 1e9, true, false, "s");
    if (!std::isinf(f.total_mass_kg))
      c.Range(name + ".total_mass_kg", f.total_mass_kg, 0, 1e9, true, false, "kg");
    c.Range(name + ".batch_interval_s", f.batch_interval_s, 0, 1e6, false, false, "s");
    c.Range(name + ".follow_heap.clearance_m", f.follow_heap_clearance_m, 0, 1e3, false, false, "m");
    c.Range(name + ".follow_heap.settled_speed_m_s", f.settled_speed_m_s, 0, 1e3, true, false, "m/s");
    c.Magnitude(name + ".velocity_m_s", f.velocity_m_s, limits::kSpeed, "m/s");
    c.Magnitude(name + ".region_velocity_m_s", f.region_velocity_m_s, limits::kSpeed, "m/s");
    for (int a = 0; a < 3; ++a)
      if (f.region.min_m[a] < s.domain_min_m[a] || f.region.max_m[a] > s.domain_max_m[a] ||
          !(f.region.max_m[a] > f.region.min_m[a]))
        c.Fail("field '" + name + ".region' must be a non-empty region inside the domain");
    if (!c.ok()) return;
    if (d_max >= f.region.MinExtent()) {
      std::ostringstream os;
      os << "field '" << name << ".region' is too small: its smallest extent "
         << f.region.MinExtent() << " m does not exceed the largest particle diameter " << d_max << " m";
      c.Fail(os.str());
      return;
    }
    // One batch must fit in the region at a solid fraction random insertion can reach (0.3).
    const double interval = ParticleFactory::BatchInterval(f, Norm(s.gravity_m_s2));
    const double batch_volume = f.mass_rate_kg_s * interval / mean_density;
    if (batch_volume > 0.3 * f.region.Volume()) {
      std::ostringstream os;
      os << "field '" << name << ".region' is too small for mass_rate_kg_s = " << f.mass_rate_kg_s
         << ": a batch of " << interval << " s needs a solid fraction of "
         << batch_volume / f.region.Volume()
         << " in it (at most 0.3); enlarge the region (taller regions also batch less often) or "
            "lower the rate";
      c.Fail(os.str());
    }
  }
}

void CheckTime(const Scene& s, Checker& c) {
  c.Range("time.duration_s", s.time.duration_s, 0, 1e6, false, false, "s");
  c.Range("time.rayleigh_fraction", s.time.rayleigh_fraction, 0, 1, true, false);
  c.Range("time.timestep_s", s.time.timestep_s, 0, 1, false, false, "s");
  c.Range("skin_m", s.skin_m, 0, 1, false, false, "m");
  c.Range("max_wall_time_s", s.max_wall_time_s, 0, 1e9, false, false, "s");
  if (!c.ok() || s.species.empty()) return;
  const double gap = MaxAdhesiveBreakGap(s);
  if (s.skin_m > 0 && s.skin_m <= gap) {
    std::ostringstream os;
    os << "field 'skin_m' = " << s.skin_m << " m must exceed the largest JKR break gap " << gap
       << " m, or stretched adhesive contacts would be lost; leave it unset for automatic";
    c.Fail(os.str());
  }
  const double t_r = RayleighTime(s);
  if (s.time.timestep_s > t_r && !s.time.force_timestep) {
    std::ostringstream os;
    os << "field 'time.timestep_s' = " << s.time.timestep_s << " s exceeds the Rayleigh time "
       << t_r << " s of the smallest, stiffest species; contacts would be under-resolved and "
       << "the run would blow up. Use time.rayleigh_fraction (default 0.2) or set "
       << "time.force_timestep = true to insist";
    c.Fail(os.str());
  }
}

}  // namespace

bool Scene::IsValid(std::string* error) const {
  Checker c(error);
  CheckMaterials(*this, c);
  if (c.ok()) CheckSpecies(*this, c);
  if (c.ok()) CheckPairs(*this, c);
  if (c.ok()) CheckGeometry(*this, c);
  if (c.ok()) CheckParticles(*this, c);
  if (c.ok()) CheckFactories(*this, c);
  for (size_t i = 0; i < sinks.size() && c.ok(); ++i) {
    const std::string problem = SinkProblem(sinks[i]);
    if (!problem.empty()) c.Fail("field '" + IndexedField("sinks", i) + problem);
    if (sinks[i].shape == SinkSpec::Shape::kPlane) {
      c.Point(IndexedField("sinks", i) + ".point_m", sinks[i].point_m);
    } else {
      c.Point(IndexedField("sinks", i) + ".min_m", sinks[i].min_m);
      c.Point(IndexedField("sinks", i) + ".max_m", sinks[i].max_m);
    }
  }
  RollingModel model;
  if (c.ok() && !MakeRollingModel(rolling, &model))
    c.Fail("field 'contact_model.rolling' = '" + rolling.name + "' is not one of none|cdt|epsd|epsd2");
  if (c.ok())
    c.Within("contact_model.epsd_damping_ratio", rolling.epsd_damping_ratio,
             limits::kDampingRatio);
  JkrRollingLoad load{};
  if (c.ok() && !ParseJkrRollingLoad(rolling.jkr_rolling_load, &load))
    c.Fail("field 'contact_model.jkr_rolling_load' = '" + rolling.jkr_rolling_load +
           "' is not one of net|repulsive");
  if (c.ok() && species.empty() && (!particles.empty() || !fills.empty() || !factories.empty()))
    c.Fail("field 'species' must list at least one species");
  if (c.ok()) CheckTime(*this, c);
  if (c.ok()) CheckSceneMotion(*this, c);
  return c.ok();
}

}  // namespace demcal::core
