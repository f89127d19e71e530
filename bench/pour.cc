#include "bench/pour.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>

#include "core/math/random.h"
#include "core/simulation/simulation.h"

namespace demcal::bench {
namespace {

using core::Vec3;

constexpr double kBaseDiameter = 0.002;

core::Scene PourScene(const PourOptions& o) {
  core::Scene s;
  s.materials = {{"glass", 5e6, 0.25, 2500}};
  s.species = {{"sphere", 0, {}, {}}};
  s.species[0].size = {core::SizeDistribution::Kind::kUniform, 0, 0.0018, 0.0022, {}, {}};
  core::PairParameters pair;
  pair.sliding_friction = 0.5;
  pair.rolling_friction = 0.1;
  pair.restitution = 0.5;
  s.pair_parameters = {pair};
  s.rolling.name = "epsd2";
  const double half = o.base_radius_m + 0.01, top = o.stream_height_m + 0.02;
  s.walls = core::BoxInnerFaces("box", {-half, -half, 0}, {half, half, top}, 0, true);
  s.domain_min_m = {-half, -half, 0};
  s.domain_max_m = {half, half, top + 0.02};
  // The frozen base: a square grid clipped to the disc, each sphere lifted at random.
  core::Rng rng(core::DeriveSeed(o.seed, 77));
  const double d = kBaseDiameter, r = 0.5 * d;
  const int n = static_cast<int>(std::floor(2 * o.base_radius_m / d));
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const Vec3 at{(i - 0.5 * (n - 1)) * d, (j - 0.5 * (n - 1)) * d, r * (1 + 0.5 * rng.Uniform())};
      if (at.x * at.x + at.y * at.y > o.base_radius_m * o.base_radius_m) continue;
      core::ParticleSpec p{0, at, {}, {}, d, {}};
      p.fixed = true;
      s.particles.push_back(p);
    }
  core::FactorySpec stream;
  stream.name = "stream";
  stream.region = core::InsertionRegion::Cylinder({0, 0, 0}, 0.005, o.stream_height_m - 0.02,
                                                  o.stream_height_m);
  stream.species = {0};
  stream.mass_fractions = {1};
  stream.mass_rate_kg_s = o.mass_rate_kg_s;
  stream.velocity_m_s = {0, 0, -1.5};  // fast enough for the rate in a 5 mm stream
  s.factories = {stream};
  s.seed = o.seed;
  s.time.timestep_s = 2.4e-5;
  s.skin_m = 0.0005;
  return s;
}

}  // namespace

CLI::App* AddPourCommand(CLI::App& app, PourOptions* o) {
  auto* c = app.add_subcommand("pour", "time the poured heap on a frozen base");
  c->add_option("--threads", o->threads, "worker threads");
  c->add_option("--steps", o->steps, "timed steps from the start of the pour");
  c->add_option("--base-radius", o->base_radius_m, "radius of the frozen base disc, m");
  c->add_option("--rate", o->mass_rate_kg_s, "mass rate of the stream, kg/s");
  c->add_flag("--keep-fixed-pairs", o->keep_fixed_pairs,
              "sweep fixed spheres like moving ones (keep fixed-fixed pairs in the list)");
  c->add_option("--refresh", o->refresh_fraction,
                 "incremental rebuilds: re-search particles beyond this fraction of the skin "
                 "from their reference (0: full rebuilds)");
  c->add_option("--seed", o->seed, "random seed");
  return c;
}

int RunPour(const PourOptions& o) {
  const core::Scene scene = PourScene(o);
  core::Simulation sim(scene, {.threads = o.threads,
                               .exclude_fixed_pairs = !o.keep_fixed_pairs,
                               .neighbour_refresh_fraction = o.refresh_fraction});
  std::string error;
  if (!sim.Initialize(&error)) {
    std::cerr << "error: " << error << "\n";
    return 1;
  }
  const size_t base = scene.particles.size();
  // Movers per rebuild (particles re-searched) against the moving particles at that rebuild.
  uint64_t last_builds = sim.neighbours().Builds();
  double movers = 0, moving = 0;
  core::Simulation::Observer count{1, [&](const core::Simulation& s) {
                                     const core::NeighbourList& list = s.neighbours();
                                     if (list.Builds() == last_builds) return true;
                                     last_builds = list.Builds();
                                     movers += list.LastMovers(), moving += list.FirstFixed();
                                     return true;
                                   }};
  const core::RunSummary run = sim.Run(o.steps * sim.timestep_s(), count);
  if (!run.ok()) {
    std::cerr << "run failed: " << run.BriefReport() << "\n";
    return 1;
  }
  const size_t spheres = sim.particles().Size();
  std::printf("threads: %d\nbase_spheres: %zu\npoured_spheres: %zu\nsteps: %lld\n", o.threads, base,
              spheres - base, static_cast<long long>(run.steps));
  std::printf("neighbour_rebuilds: %llu\nneighbour_pairs: %zu\nwall_time_s: %.3f\n",
              static_cast<unsigned long long>(run.neighbour_rebuilds),
              sim.neighbours().PairCount(), run.wall_time_s);
  std::printf("re-searched per rebuild: %.0f of %.0f moving spheres on average\n",
              movers / std::max<double>(1, run.neighbour_rebuilds),
              moving / std::max<double>(1, run.neighbour_rebuilds));
  std::printf("phases: %s\n", run.phases.Report().c_str());
  return 0;
}

}  // namespace demcal::bench
