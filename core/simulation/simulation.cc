#include "core/simulation/simulation.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <chrono>
#include <numeric>
#include <cmath>
#include <sstream>

#include "core/contact/normal_model.h"
#include "core/insertion/insertion.h"
#include "core/math/number_text.h"
#include "core/math/random.h"
#include "core/math/seed_streams.h"

namespace demcal::core {
namespace {
int ArenaConcurrency(int threads) {
  return threads > 0 ? threads : static_cast<int>(tbb::task_arena::automatic);
}

// Upper bound of the energy a particle can gain from the normal law's attraction, for at most
// 12 contacts of the scene's largest spheres (the law's AttractionEnergyBound).
double AdhesiveEnergyBoundPerParticle(const Scene& scene, const InteractionTable& table,
                                      const NormalModel& normal) {
  const double r = 0.5 * scene.MaxDiameter();
  return std::visit(
      [&](const auto& law) {
        double bound = 0;
        for (int i = 0; i < table.MaterialCount(); ++i)
          for (int j = 0; j < table.MaterialCount(); ++j)
            bound = std::max(bound, law.AttractionEnergyBound(r, table.Get(i, j), 12));
        return bound;
      },
      normal);
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

void Simulation::SetBalanceProbe(int chunks) {
  options_.balance_probe_chunks = chunks;
  forces_.SetBalanceProbe(chunks);
}

bool Simulation::Initialize(std::string* error) {
  if (!scene_.IsValid(error)) return false;
  table_ = InteractionTable(scene_.materials, scene_.pair_parameters);
  MakeRollingModel(scene_.rolling, &rolling_);
  MakeNormalModel(scene_.pair_parameters, scene_.rolling, &normal_);
  dt_ = TimeStep(scene_);
  if (!system_.SetSpecies(scene_.species, error)) return false;
  std::string placement_error;
  PlaceInitialParticles(&placement_error);
  if (!placement_error.empty()) {
    if (error) *error = placement_error;
    return false;
  }
  adhesive_gap_m_ = MaxAdhesiveBreakGap(scene_);
  PeriodicBox box{scene_.domain_min_m, {}};
  for (int a = 0; a < 3; ++a)
    if (scene_.periodic[a]) box.length_m[a] = scene_.domain_max_m[a] - scene_.domain_min_m[a];
  list_settings_ = {scene_.domain_min_m, scene_.domain_max_m, NeighbourSkin(scene_),
                    0.5 * scene_.MaxDiameter(), box};
  forces_.SetPeriodic(box);
  forces_.SetBalanceProbe(options_.balance_probe_chunks);
  walls_ = scene_.walls;
  walls_move_ = false;
  for (const Wall& w : walls_) walls_move_ = walls_move_ || w.Moves();
  PlaceWalls(time_s_);
  WallRemovedDuringStep(time_s_);
  sink_reports_.clear();
  for (const SinkSpec& sink : scene_.sinks)
    sink_reports_.push_back({sink.name, std::vector<int64_t>(scene_.species.size(), 0),
                             std::vector<double>(scene_.species.size(), 0.0)});
  if (!scene_.sinks.empty())
    sink_reports_.push_back({"domain", std::vector<int64_t>(scene_.species.size(), 0),
                             std::vector<double>(scene_.species.size(), 0.0)});
  arena_->execute([&] {
    RebuildNeighbours(true);
    ComputeForces(time_s_);
    system_.ReduceClumpForces(scene_.gravity_m_s2);
  });
  CreateFactories();
  const Vec3 g = scene_.gravity_m_s2;
  // Initial overlaps (explicitly placed particles) release their elastic energy.
  const double elastic = forces_.PairElasticEnergy(system_.spheres, list_, table_);
  energy_budget_J_ = system_.KineticEnergy() + system_.GravitationalPotential(g) + elastic;
  // Largest energy gravity can release: every particle dropping to the domain's lowest corner.
  lowest_point_ = {g.x > 0 ? scene_.domain_max_m.x : scene_.domain_min_m.x,
                   g.y > 0 ? scene_.domain_max_m.y : scene_.domain_min_m.y,
                   g.z > 0 ? scene_.domain_max_m.z : scene_.domain_min_m.z};
  energy_scale_J_ = system_.KineticEnergy() + elastic +
                    system_.spheres.Size() *
                        AdhesiveEnergyBoundPerParticle(scene_, table_, normal_) +
                    system_.ReleasableGravitationalEnergy(g, lowest_point_);
  initial_bodies_ = system_.BodyCount();
  initial_energy_scale_J_ = energy_scale_J_;
  inserted_energy_bound_J_ =
      InsertedEnergyBound(AdhesiveEnergyBoundPerParticle(scene_, table_, normal_));
  initialized_ = true;
  return true;
}

void Simulation::PlaceInitialParticles(std::string* error) {
  Rng rng(DeriveSeed(scene_.seed, kInitialParticlesStream));
  for (const ParticleSpec& p : scene_.particles) {
    const Species& sp = scene_.species[p.species];
    const double d = p.diameter_m > 0 ? p.diameter_m : sp.size.Sample(rng.Uniform());
    system_.Add(p.species, sp.material, scene_.materials[sp.material].density_kg_m3, d,
                p.position_m, p.velocity_m_s, p.angular_velocity_rad_s, p.orientation);
    if (p.fixed) system_.spheres.Fix(system_.spheres.Size() - 1);
  }
  for (size_t f = 0; f < scene_.fills.size(); ++f) {
    const FillSpec& fill = scene_.fills[f];
    const Species& sp = scene_.species[fill.species];
    Rng fill_rng(DeriveSeed(scene_.seed, kFillStreamBase + f));
    InsertionRequest q;
    q.region = fill.region;
    q.mixture = {{fill.species, sp.material, scene_.materials[sp.material].density_kg_m3, &sp.size, 1}};
    q.max_count = fill.count;
    q.velocity_m_s = fill.velocity_m_s;
    const InsertionResult placed = InsertRandomNonOverlapping(q, fill_rng, system_);
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
                            DeriveSeed(scene_.seed, kFactoryStreamBase + f));
  }
}

bool Simulation::InsertFromFactories() {
  const size_t first_sphere = system_.spheres.Size(), first_clump = system_.clumps.Size();
  for (ParticleFactory& factory : factories_) factory.Update(time_s_, system_);
  if (system_.spheres.Size() == first_sphere) return false;
  // The newcomers bring kinetic and potential energy (and adhesion) into the budget; summed
  // over them only (a sum over the whole bed before and after cost a pass per step).
  const Vec3 g = scene_.gravity_m_s2;
  const double kinetic = system_.KineticEnergySince(first_sphere, first_clump);
  energy_budget_J_ +=
      kinetic + system_.ReleasableGravitationalEnergy(g, {}, first_sphere, first_clump);
  energy_scale_J_ += kinetic +
                     (system_.spheres.Size() - first_sphere) *
                         AdhesiveEnergyBoundPerParticle(scene_, table_, normal_) +
                     system_.ReleasableGravitationalEnergy(g, lowest_point_, first_sphere, first_clump);
  return true;
}

std::vector<FactoryReport> Simulation::FactoryReports() const {
  std::vector<FactoryReport> reports;
  for (const ParticleFactory& f : factories_) reports.push_back(f.report());
  return reports;
}

const FactoryReport* Simulation::FindFactoryReport(const std::string& name) const {
  for (const ParticleFactory& f : factories_)
    if (f.report().name == name) return &f.report();
  return nullptr;
}

std::vector<std::string> Simulation::FactoryRateWarnings() const {
  std::vector<std::string> warnings;
  for (const ParticleFactory& f : factories_)
    if (std::string w = f.RateWarning(); !w.empty()) warnings.push_back(std::move(w));
  return warnings;
}

void Simulation::RebuildNeighbours(bool allow_reorder, const std::vector<uint32_t>& removed) {
  std::swap(list_, spare_list_);
  std::vector<uint32_t> order;
  const bool reorder = allow_reorder && options_.reorder_every_rebuilds > 0 &&
                       rebuilds_since_reorder_ % options_.reorder_every_rebuilds == 0;
  Particles& p = system_.spheres;
  const size_t n = p.Size();
  size_t moving = n;
  bool fixed_last = true;  // every fixed sphere after every moving one
  std::vector<uint8_t> swept;  // per slot, for a re-sort: whether the force sweep visits it
  if (options_.exclude_fixed_pairs) {
    moving = p.CountMoving(0, n);
    fixed_last = p.CountMoving(0, moving) == moving;
    if (reorder) {
      swept.resize(n);
      tbb::parallel_for(tbb::blocked_range<size_t>(0, n), [&](const auto& range) {
        for (size_t i = range.begin(); i != range.end(); ++i) swept[i] = !p.IsFixed(i);
      });
    }
  }
  if (reorder || !fixed_last) {
    if (reorder) {
      order = spare_list_.CellOrder(list_settings_, p.position_m, swept);
    } else {
      order.resize(n);
      std::iota(order.begin(), order.end(), 0u);
    }
    // Moving spheres first (each part in cell order): the integration and force loops then
    // stream over moving particles only; newcomers from factories join the moving part.
    if (options_.exclude_fixed_pairs)
      std::stable_partition(order.begin(), order.end(), [&](uint32_t s) { return !p.IsFixed(s); });
    order = system_.GroupClumpMembers(order);
    system_.Permute(order);
  }
  ++rebuilds_since_reorder_;
  if (!removed.empty() || slots_before_removal_ > 0) {
    // The history transfer needs each slot's slot before this step: compose with the removal
    // (newcomers appended after it map past the old slots: no history).
    if (order.empty()) {
      order.resize(n);
      std::iota(order.begin(), order.end(), 0u);
    }
    for (uint32_t& s : order)
      s = s < removed.size() ? removed[s]
                             : static_cast<uint32_t>(slots_before_removal_ + (s - removed.size()));
    slots_before_removal_ = 0;
  }
  const std::vector<int>* body = system_.clumps.Size() ? &p.body : nullptr;
  // Same slots, or the same less those a sink took: keep the unmoved particles' rows.
  const NeighbourList* previous = nullptr;
  if (options_.neighbour_refresh_fraction > 0) {
    if (order.empty()) previous = &spare_list_;
    else if (compacted_list_.CompactFrom(spare_list_, order, moving)) previous = &compacted_list_;
  }
  if (previous)
    list_.Update(list_settings_, p.position_m, p.radius_m, body, moving, *previous,
                 options_.neighbour_refresh_fraction);
  else
    list_.Build(list_settings_, p.position_m, p.radius_m, body, moving);
  forces_.Rebuild(p, spare_list_, list_, order, walls_, list_settings_.skin_m, adhesive_gap_m_);
}

void Simulation::PlaceWalls(double time_s) {
  if (!walls_move_) return;
  for (size_t w = 0; w < walls_.size(); ++w) {
    const Wall& initial = scene_.walls[w];
    if (!initial.Moves()) continue;
    const Vec3 d = initial.DisplacementAt(time_s);
    ShapeOrigin(walls_[w].shape) = ShapeOrigin(initial.shape) + d;
    walls_[w].load_point_m = initial.load_point_m + d;
  }
}

void Simulation::AddWallWork(double time_s) {
  if (!walls_move_) return;
  const std::vector<WallLoad> loads = WallLoads();
  double work = 0;  // by the walls on the particles: −(force on the wall) · v Δt
  for (size_t w = 0; w < walls_.size(); ++w)
    work -= Dot(loads[w].force_N, walls_[w].VelocityAt(time_s)) * dt_;
  energy_budget_J_ += work;
  energy_scale_J_ += std::abs(work);
}

void Simulation::ComputeForces(double time_s) {
  forces_.SetBodyCentres(system_.clumps.position_m);  // may have moved since the last step
  forces_.Compute(system_.spheres, list_, walls_, time_s, table_, normal_, rolling_,
                  scene_.gravity_m_s2, dt_);
}

void Simulation::Step(bool defer_kick) {
  auto last = std::chrono::steady_clock::now();
  auto lap = [&](double& phase_s) {
    const auto now = std::chrono::steady_clock::now();
    phase_s += std::chrono::duration<double>(now - last).count();
    last = now;
  };
  system_.KickDrift(dt_, list_.FirstFixed(), kick_pending_);
  kick_pending_ = false;
  if (list_settings_.periodic.Any()) system_.WrapPeriodic(list_settings_.periodic);
  lap(phases_.integrate_s);
  const double t = time_s_ + dt_;  // the time of the drifted positions
  PlaceWalls(t);
  const bool wall_removed = WallRemovedDuringStep(t);
  const bool inserted = !factories_.empty() && InsertFromFactories();
  lap(phases_.insert_s);
  const bool rebuild = inserted || wall_removed || list_.NeedsRebuild(system_.spheres.position_m);
  lap(phases_.rebuild_check_s);
  if (rebuild) {
    // Sinks take their particles at a rebuild (the slots change, so the list is built anew),
    // at most once per sink_every_steps: removal then costs a full build now and then.
    bool removed = false;
    if (!sink_reports_.empty() && steps_ + 1 - last_sink_pass_step_ >= options_.sink_every_steps) {
      last_sink_pass_step_ = steps_ + 1;
      removed = RemoveSunkParticles();
    }
    RebuildNeighbours(true, removed ? removal_order_ : std::vector<uint32_t>{});
    rebuild_search_.searched += list_.LastMovers();
    rebuild_search_.moving += list_.FirstFixed();
    lap(phases_.rebuild_s);
  }
  ComputeForces(t);
  AddWallWork(t);
  lap(phases_.forces_s);
  system_.ReduceAndKick(scene_.gravity_m_s2, dt_, list_.FirstFixed(), defer_kick);
  kick_pending_ = defer_kick;
  lap(phases_.integrate_s);
  time_s_ += dt_;
  ++steps_;
}

RunSummary Simulation::Run(double duration_s) { return Run(duration_s, Observer{}); }

RunSummary Simulation::Run(double duration_s, const Observer& observer) {
  RunSummary s;
  if (!initialized_) {
    s.message = "Initialize() was not called or failed";
    return s;
  }
  const auto start = std::chrono::steady_clock::now();
  const uint64_t builds_before = list_.Builds() + spare_list_.Builds();
  auto elapsed = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  const int64_t n_steps = std::max<int64_t>(0, std::llround(duration_s / dt_));
  const PhaseTimes phases_before = phases_;
  const RebuildSearch search_before = rebuild_search_;
  const SweepBalance balance_before = forces_.sweep_balance();
  s.termination = Termination::kOk;
  s.message = "completed";
  arena_->execute([&] {
    for (int64_t k = 0; k < n_steps; ++k) {
      const bool last = k + 1 == n_steps;
      const bool check_due = (k + 1) % options_.check_every_steps == 0 || last;
      const bool observer_due = observer.callback && observer.every_steps > 0 &&
                                (steps_ + 1) % observer.every_steps == 0;
      Step(/*defer_kick=*/!check_due && !observer_due);
      const auto checks_start = std::chrono::steady_clock::now();
      const auto add_check_time = [&] {
        phases_.checks_s += std::chrono::duration<double>(std::chrono::steady_clock::now() -
                                                          checks_start).count();
      };
      if (check_due) {
        s.termination = Check(&s.message);
        if (s.termination == Termination::kOk && scene_.max_wall_time_s > 0 &&
            elapsed() > scene_.max_wall_time_s) {
          s.termination = Termination::kWallTimeExceeded;
          s.message = "wall-time budget of " + NumberText(scene_.max_wall_time_s) +
                      " s exceeded at t = " + NumberText(time_s_) + " s";
        }
        if (s.termination != Termination::kOk) break;
      }
      if (observer.callback && observer.every_steps > 0 && steps_ % observer.every_steps == 0 &&
          !observer.callback(*this)) {
        s.message = "stopped by observer";
        break;
      }
      add_check_time();
    }
  });
  s.steps = steps_;
  s.simulated_time_s = time_s_;
  s.wall_time_s = elapsed();
  s.particles = static_cast<int64_t>(system_.BodyCount());
  s.timestep_s = dt_;
  s.final_kinetic_energy_J = system_.KineticEnergy();
  s.neighbour_rebuilds = list_.Builds() + spare_list_.Builds() - builds_before;
  s.phases = phases_;
  s.phases -= phases_before;
  s.rebuild_search = rebuild_search_;
  s.rebuild_search -= search_before;
  s.sweep_balance = forces_.sweep_balance();
  s.sweep_balance -= balance_before;
  return s;
}

}  // namespace demcal::core
