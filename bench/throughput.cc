// demcal_bench throughput: the side-by-side case of bench/README.md (LIGGGHTS reference case):
// 20,000 spheres, d = 2 mm, ρ = 2500 kg/m³, E = 5 MPa, ν = 0.25, e = 0.5, μs = 0.5, μr = 0.1
// (epsd2), 60 × 60 mm box, Δt = 2.4e-5 s, skin 0.5 mm. Pours and settles the bed (or loads it
// from --bed), runs a warm-up, then times --steps steps and prints particle-steps per second.
#include <CLI/CLI.hpp>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>

#include "core/simulation.h"

using namespace demcal::core;

namespace {

Scene BenchScene(int particles, uint64_t seed) {
  Scene s;
  s.materials = {{"glass", 5e6, 0.25, 2500}};
  s.species = {{"sphere", 0, {}, {}}};
  s.species[0].size.diameter_m = 0.002;
  PairParameters pair;
  pair.sliding_friction = 0.5;
  pair.rolling_friction = 0.1;
  pair.restitution = 0.5;
  s.pair_parameters = {pair};
  s.rolling.name = "epsd2";
  s.walls = BoxInnerFaces("box", {0, 0, 0}, {0.06, 0.06, 0.16}, 0, /*open_top=*/true);
  s.domain_min_m = {0, 0, 0};
  s.domain_max_m = {0.06, 0.06, 0.2};
  s.fills.push_back({0, {0.001, 0.001, 0.001}, {0.059, 0.059, 0.159}, particles, {0, 0, -0.5}});
  s.seed = seed;
  s.time.timestep_s = 2.4e-5;
  s.skin_m = 0.0005;
  return s;
}

// The bed file stores positions and velocities (not contact histories; the warm-up rebuilds them).
void SaveBed(const std::string& path, const Particles& p) {
  std::ofstream out(path, std::ios::binary);
  const uint64_t n = p.Size();
  out.write(reinterpret_cast<const char*>(&n), sizeof n);
  out.write(reinterpret_cast<const char*>(p.position_m.data()), n * sizeof(Vec3));
  out.write(reinterpret_cast<const char*>(p.velocity_m_s.data()), n * sizeof(Vec3));
  out.write(reinterpret_cast<const char*>(p.angular_velocity_rad_s.data()), n * sizeof(Vec3));
}

bool LoadBed(const std::string& path, Scene& scene) {
  std::ifstream in(path, std::ios::binary);
  uint64_t n = 0;
  if (!in.read(reinterpret_cast<char*>(&n), sizeof n)) return false;
  std::vector<Vec3> x(n), v(n), w(n);
  in.read(reinterpret_cast<char*>(x.data()), n * sizeof(Vec3));
  in.read(reinterpret_cast<char*>(v.data()), n * sizeof(Vec3));
  in.read(reinterpret_cast<char*>(w.data()), n * sizeof(Vec3));
  if (!in) return false;
  scene.fills.clear();
  for (uint64_t i = 0; i < n; ++i) scene.particles.push_back({0, x[i], v[i], w[i], 0.002, {}});
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"demcal throughput benchmark (see bench/README.md)"};
  app.require_subcommand(1);
  auto* tp = app.add_subcommand("throughput", "time the dense-bed case");
  int threads = 1, particles = 20000;
  int64_t steps = 10000, warmup = 200, settle_steps = 16000;
  std::string bed;
  uint64_t seed = 1;
  tp->add_option("--threads", threads, "worker threads");
  tp->add_option("--steps", steps, "timed steps");
  tp->add_option("--warmup-steps", warmup, "untimed steps before timing");
  tp->add_option("--settle-steps", settle_steps, "pour-and-settle steps when no bed is given");
  tp->add_option("--particles", particles, "particle count");
  tp->add_option("--bed", bed, "settled bed file: loaded if present, else written after settling");
  tp->add_option("--seed", seed, "random seed of the pour");
  CLI11_PARSE(app, argc, argv);

  Scene scene = BenchScene(particles, seed);
  const bool have_bed = !bed.empty() && LoadBed(bed, scene);
  Simulation sim(scene, {.threads = 0});
  std::string error;
  if (!sim.Initialize(&error)) {
    std::cerr << "error: " << error << "\n";
    return 1;
  }
  if (!have_bed) {
    std::cerr << "settling " << sim.particles().Size() << " particles for " << settle_steps << " steps...\n";
    const RunSummary settle = sim.Run(settle_steps * sim.timestep_s());
    std::cerr << "settled: " << settle.BriefReport() << "\n";
    if (!settle.ok()) return 1;
    if (!bed.empty()) SaveBed(bed, sim.particles());
  }
  sim.SetThreads(threads);
  sim.Run(warmup * sim.timestep_s());
  const RunSummary timed = sim.Run(steps * sim.timestep_s());
  if (!timed.ok()) {
    std::cerr << "timed run failed: " << timed.BriefReport() << "\n";
    return 1;
  }
  double zmax = 0;
  for (const Vec3& x : sim.particles().position_m) zmax = std::max(zmax, x.z);
  const double rate = static_cast<double>(sim.particles().Size()) * steps / timed.wall_time_s;
  std::printf("threads: %d\nparticles: %zu\nsteps: %lld\nwall_time_s: %.3f\n", threads,
              sim.particles().Size(), static_cast<long long>(steps), timed.wall_time_s);
  std::printf("bed_height_m: %.4f\nneighbour_pairs_per_particle: %.2f\n", zmax + 0.001,
              static_cast<double>(sim.neighbours().PairCount()) / sim.particles().Size());
  std::printf("contacts_per_particle: %.2f\nneighbour_rebuilds: %llu\n",
              static_cast<double>(sim.ActiveContacts()) / sim.particles().Size(),
              static_cast<unsigned long long>(timed.neighbour_rebuilds));
  // Order-independent digest of the final state: equal across thread counts iff bit-identical.
  double digest = 0;
  for (size_t i = 0; i < sim.particles().Size(); ++i)
    digest += sim.particles().position_m[i].x * (1 + sim.particles().id[i] % 7) +
              sim.particles().velocity_m_s[i].z;
  std::printf("state_digest: %a\n", digest);
  std::printf("particle_steps_per_s: %.0f\n", rate);
  return 0;
}
