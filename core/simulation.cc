#include "core/simulation.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include <chrono>
#include <cmath>
#include <numbers>
#include <sstream>

#include "core/contact/jkr.h"
#include "core/insertion.h"
#include "core/random.h"

namespace demcal::core {
namespace {
int ArenaConcurrency(int threads) {
  return threads > 0 ? threads : static_cast<int>(tbb::task_arena::automatic);
}

// Upper bound of the energy a particle can gain from JKR attraction: per contact at most
// F_c (3|δ_min|) (the attractive force never exceeds F_c over a travel of δ_eq − δ_min), for at
// most 12 contacts.
double AdhesiveEnergyBoundPerParticle(const Scene& scene, const InteractionTable& table) {
  const double r = 0.5 * scene.MaxDiameter();
  double bound = 0;
  for (int i = 0; i < table.MaterialCount(); ++i)
    for (int j = 0; j < table.MaterialCount(); ++j) {
      const ResolvedPair& p = table.Get(i, j);
      if (p.interfacial_energy_J_m2 <= 0) continue;
      const double f_c = 3 * std::numbers::pi * p.interfacial_energy_J_m2 * r;
      const double gap = JkrNormal::BreakGap(r, p.effective_youngs_Pa, p.interfacial_energy_J_m2);
      bound = std::max(bound, 12 * f_c * 3 * gap);
    }
  return bound;
}
}  // namespace

Simulation::Simulation(Scene scene) : Simulation(std::move(scene), Options{}) {}

Simulation::Simulation(Scene scene, Options options)
    : scene_(std::move(scene)),
      options_(options),
      arena_(std::make_unique<tbb::task_arena>(ArenaConcurrency(options.threads))) {}

Simulation::~Simulation() = default;

void Simulation::SetThreads(int threads) {
  options_.threads = threads;
  arena_ = std::make_unique<tbb::task_arena>(ArenaConcurrency(threads));
}

bool Simulation::Initialize(std::string* error) {
  if (!scene_.IsValid(error)) return false;
  table_ = InteractionTable(scene_.materials, scene_.pair_parameters);
  MakeRollingModel(scene_.rolling, &rolling_);
  dt_ = scene_.time.timestep_s > 0 ? scene_.time.timestep_s
                                   : scene_.time.rayleigh_fraction * RayleighTime(scene_);
  std::string placement_error;
  PlaceInitialParticles(&placement_error);
  if (!placement_error.empty()) {
    if (error) *error = placement_error;
    return false;
  }
  adhesive_ = false;
  for (const PairParameters& pair : scene_.pair_parameters)
    adhesive_ = adhesive_ || pair.interfacial_energy_J_m2 > 0;
  list_settings_ = {scene_.domain_min_m, scene_.domain_max_m, NeighbourSkin(scene_),
                    0.5 * scene_.MaxDiameter()};
  arena_->execute([&] {
    RebuildNeighbours(true);
    forces_.Compute(particles_, list_, scene_.walls, table_, rolling_, adhesive_,
                    scene_.gravity_m_s2, dt_);
  });
  CreateFactories();
  energy_budget_J_ = particles_.KineticEnergy() + GravitationalPotential();
  // Largest energy gravity can release: every particle dropping to the domain's lowest corner.
  const Vec3 g = scene_.gravity_m_s2;
  lowest_point_ = {g.x > 0 ? scene_.domain_max_m.x : scene_.domain_min_m.x,
                   g.y > 0 ? scene_.domain_max_m.y : scene_.domain_min_m.y,
                   g.z > 0 ? scene_.domain_max_m.z : scene_.domain_min_m.z};
  energy_scale_J_ = particles_.KineticEnergy() +
                    particles_.Size() * AdhesiveEnergyBoundPerParticle(scene_, table_);
  for (size_t i = 0; i < particles_.Size(); ++i)
    energy_scale_J_ += particles_.mass_kg[i] * Dot(g, lowest_point_ - particles_.position_m[i]);
  initialized_ = true;
  return true;
}

void Simulation::PlaceInitialParticles(std::string* error) {
  Rng rng(DeriveSeed(scene_.seed, 0));
  for (const ParticleSpec& p : scene_.particles) {
    const Species& sp = scene_.species[p.species];
    const double d = p.diameter_m > 0 ? p.diameter_m : sp.size.Sample(rng.Uniform());
    particles_.Add(next_id_++, p.species, sp.material, 0.5 * d,
                   scene_.materials[sp.material].density_kg_m3, p.position_m, p.velocity_m_s,
                   p.angular_velocity_rad_s);
  }
  for (size_t f = 0; f < scene_.fills.size(); ++f) {
    const FillSpec& fill = scene_.fills[f];
    const Species& sp = scene_.species[fill.species];
    Rng fill_rng(DeriveSeed(scene_.seed, 1 + f));
    InsertionRequest q;
    q.region = InsertionRegion::Box(fill.region_min_m, fill.region_max_m);
    q.mixture = {{fill.species, sp.material, scene_.materials[sp.material].density_kg_m3, &sp.size, 1}};
    q.max_count = fill.count;
    q.velocity_m_s = fill.velocity_m_s;
    const InsertionResult placed = InsertRandomNonOverlapping(q, fill_rng, particles_, next_id_);
    if (placed.count < fill.count) {
      std::ostringstream os;
      os << "fills[" << f << "]: placed only " << placed.count << " of " << fill.count
         << " particles: the region is too small for that count (it would need a solid fraction of "
         << fill.count * sp.size.MeanVolume() / q.region.Volume()
         << "; random insertion works up to about 0.3)";
      *error = os.str();
      return;
    }
  }
}

void Simulation::CreateFactories() {
  factories_.clear();
  for (size_t f = 0; f < scene_.factories.size(); ++f) {
    const FactorySpec& spec = scene_.factories[f];
    std::vector<SpeciesDraw> mixture;
    for (int s : spec.species) {
      const Species& sp = scene_.species[s];
      mixture.push_back({s, sp.material, scene_.materials[sp.material].density_kg_m3, &scene_.species[s].size, 1});
    }
    factories_.emplace_back(spec, std::move(mixture), Norm(scene_.gravity_m_s2),
                            DeriveSeed(scene_.seed, 1000 + f));
  }
}

bool Simulation::InsertFromFactories() {
  const size_t first = particles_.Size();
  for (ParticleFactory& factory : factories_) factory.Update(time_s_, particles_, next_id_);
  if (particles_.Size() == first) return false;
  AccountInsertedEnergy(first);
  return true;
}

void Simulation::AccountInsertedEnergy(size_t first) {
  const Vec3 g = scene_.gravity_m_s2;
  const double adhesion = AdhesiveEnergyBoundPerParticle(scene_, table_);
  for (size_t i = first; i < particles_.Size(); ++i) {
    const double m = particles_.mass_kg[i];
    const double kinetic = 0.5 * m * Norm2(particles_.velocity_m_s[i]);
    energy_budget_J_ += kinetic - m * Dot(g, particles_.position_m[i]);
    energy_scale_J_ += kinetic + adhesion + m * Dot(g, lowest_point_ - particles_.position_m[i]);
  }
}

std::vector<FactoryReport> Simulation::FactoryReports() const {
  std::vector<FactoryReport> reports;
  for (const ParticleFactory& f : factories_) reports.push_back(f.report());
  return reports;
}

void Simulation::RebuildNeighbours(bool allow_reorder) {
  std::swap(list_, spare_list_);
  std::vector<uint32_t> order;
  const bool reorder = allow_reorder && options_.reorder_every_rebuilds > 0 &&
                       rebuilds_since_reorder_ % options_.reorder_every_rebuilds == 0;
  if (reorder) {
    order = spare_list_.CellOrder(list_settings_, particles_.position_m);
    particles_.Permute(order);
  }
  ++rebuilds_since_reorder_;
  list_.Build(list_settings_, particles_.position_m, particles_.radius_m);
  forces_.Rebuild(particles_, spare_list_, list_, order, scene_.walls, list_settings_.skin_m);
}

void Simulation::Step() {
  const size_t n = particles_.Size();
  const double half = 0.5 * dt_;
  Particles& p = particles_;
  auto kick = [&](size_t i) {
    p.velocity_m_s[i] += p.force_N[i] * (half * p.inv_mass[i]);
    p.angular_velocity_rad_s[i] += p.torque_N_m[i] * (half * p.inv_inertia[i]);
  };
  tbb::parallel_for(tbb::blocked_range<size_t>(0, n, 1024), [&](const auto& range) {
    for (size_t i = range.begin(); i != range.end(); ++i) {
      kick(i);
      p.position_m[i] += p.velocity_m_s[i] * dt_;
    }
  });
  const bool inserted = !factories_.empty() && InsertFromFactories();
  if (inserted || list_.NeedsRebuild(p.position_m)) RebuildNeighbours(true);
  forces_.Compute(p, list_, scene_.walls, table_, rolling_, adhesive_, scene_.gravity_m_s2, dt_);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, p.Size(), 1024), [&](const auto& range) {
    for (size_t i = range.begin(); i != range.end(); ++i) kick(i);
  });
  time_s_ += dt_;
  ++steps_;
}

double Simulation::GravitationalPotential() const {
  double e = 0;
  for (size_t i = 0; i < particles_.Size(); ++i)
    e -= particles_.mass_kg[i] * Dot(scene_.gravity_m_s2, particles_.position_m[i]);
  return e;
}

Termination Simulation::Check(std::string* message) const {
  const Particles& p = particles_;
  const Vec3 lo = scene_.domain_min_m, hi = scene_.domain_max_m;
  struct Found { int64_t non_finite = -1, outside = -1; };
  const Found found = tbb::parallel_reduce(
      tbb::blocked_range<size_t>(0, p.Size()), Found{},
      [&](const auto& range, Found f) {
        for (size_t i = range.begin(); i != range.end(); ++i) {
          const Vec3& x = p.position_m[i];
          if (f.non_finite < 0 && (!IsFinite(x) || !IsFinite(p.velocity_m_s[i]) ||
                                   !IsFinite(p.angular_velocity_rad_s[i])))
            f.non_finite = static_cast<int64_t>(i);
          if (f.outside < 0 && (x.x < lo.x || x.y < lo.y || x.z < lo.z || x.x > hi.x ||
                                x.y > hi.y || x.z > hi.z))
            f.outside = static_cast<int64_t>(i);
        }
        return f;
      },
      [](Found a, Found b) {
        if (a.non_finite < 0 || (b.non_finite >= 0 && b.non_finite < a.non_finite)) a.non_finite = b.non_finite;
        if (a.outside < 0 || (b.outside >= 0 && b.outside < a.outside)) a.outside = b.outside;
        return a;
      });
  std::ostringstream os;
  if (found.non_finite >= 0) {
    os << "particle id " << p.id[found.non_finite] << " has a non-finite position or velocity at t = "
       << time_s_ << " s (time step " << dt_ << " s too large, or invalid contact parameters)";
    *message = os.str();
    return Termination::kNonFinite;
  }
  if (found.outside >= 0) {
    const Vec3& x = p.position_m[found.outside];
    os << "particle id " << p.id[found.outside] << " left the domain at t = " << time_s_
       << " s, position (" << x.x << ", " << x.y << ", " << x.z
       << ") m; close the container with walls or enlarge 'domain'";
    *message = os.str();
    return Termination::kParticlesLost;
  }
  const double energy = p.KineticEnergy() + GravitationalPotential();
  if (energy - energy_budget_J_ > 0.5 * energy_scale_J_ + 1e-30) {
    os << "mechanical energy grew from " << energy_budget_J_ << " J to " << energy
       << " J at t = " << time_s_ << " s with no energy input: the integration is unstable "
       << "(reduce the time step; it is " << dt_ << " s)";
    *message = os.str();
    return Termination::kEnergyBlowUp;
  }
  return Termination::kOk;
}

RunSummary Simulation::Run(double duration_s) { return Run(duration_s, Observer{}); }

RunSummary Simulation::Run(double duration_s, const Observer& observer) {
  RunSummary s;
  if (!initialized_) {
    s.message = "Initialize() was not called or failed";
    return s;
  }
  const auto start = std::chrono::steady_clock::now();
  auto elapsed = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  const int64_t n_steps = std::max<int64_t>(0, std::llround(duration_s / dt_));
  s.termination = Termination::kOk;
  s.message = "completed";
  arena_->execute([&] {
    for (int64_t k = 0; k < n_steps; ++k) {
      Step();
      const bool last = k + 1 == n_steps;
      if ((k + 1) % options_.check_every_steps == 0 || last) {
        s.termination = Check(&s.message);
        if (s.termination == Termination::kOk && scene_.max_wall_time_s > 0 &&
            elapsed() > scene_.max_wall_time_s) {
          s.termination = Termination::kWallTimeExceeded;
          s.message = "wall-time budget of " + std::to_string(scene_.max_wall_time_s) +
                      " s exceeded at t = " + std::to_string(time_s_) + " s";
        }
        if (s.termination != Termination::kOk) break;
      }
      if (observer.callback && observer.every_steps > 0 && (k + 1) % observer.every_steps == 0 &&
          !observer.callback(*this)) {
        s.message = "stopped by observer";
        break;
      }
    }
  });
  s.steps = steps_;
  s.simulated_time_s = time_s_;
  s.wall_time_s = elapsed();
  s.particles = static_cast<int64_t>(particles_.Size());
  s.timestep_s = dt_;
  s.final_kinetic_energy_J = particles_.KineticEnergy();
  s.neighbour_rebuilds = list_.Builds() + spare_list_.Builds();
  return s;
}

}  // namespace demcal::core
