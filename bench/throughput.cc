// demcal_bench throughput: the side-by-side case of bench/README.md (LIGGGHTS reference case):
// 20,000 spheres, d = 2 mm, ρ = 2500 kg/m³, E = 5 MPa, ν = 0.25, e = 0.5, μs = 0.5, μr = 0.1
// (epsd2), 60 × 60 mm box, Δt = 2.4e-5 s, skin 0.5 mm. Pours and settles the bed (or loads it
// from --bed), runs a warm-up, then times --steps steps and prints particle-steps per second.
// Variants of the same case:
//   --clump N            the particles are rigid rods of N spheres of that diameter, centres one
//                        radius apart (bench/liggghts/in.clump builds the same clump), about
//                        --particles / N of them in a taller box (they are poured from higher up);
//   --jkr-cohesion Coh   JKR adhesion with Γ chosen so that the cohesion number
//                        Coh = (1/(ρg)) [Γ⁵ / (E*² R*⁸)]^{1/3} (docs/physics.md §6) has this value.
// particle_steps_per_s counts bodies (clumps or free spheres); sphere_steps_per_s counts spheres.
#include <CLI/CLI.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "bench/pour.h"
#include "core/bodies/clump_template.h"
#include "core/simulation/simulation.h"

using namespace demcal::core;

namespace {

constexpr double kDiameter = 0.002, kDensity = 2500, kYoungs = 5e6, kPoisson = 0.25;
constexpr double kGravity = 9.81;

struct CaseOptions {
  int particles = 20000;  // spheres; with clumps, member spheres (bodies = particles / N)
  int clump_spheres = 0;  // 0: plain spheres
  double cohesion = 0;    // JKR cohesion number; 0: Hertz–Mindlin
  uint64_t seed = 1;
};

// N spheres of the bench diameter in a row along x, centres one radius apart.
std::vector<ShapeSphere> RodClump(int n) {
  std::vector<ShapeSphere> rod;
  const double r = 0.5 * kDiameter;
  for (int k = 0; k < n; ++k) rod.push_back({{(k - 0.5 * (n - 1)) * r, 0, 0}, r});
  return rod;
}

// Equivalent-volume diameter of a clump shape as given (in metres).
double EquivalentDiameter(const std::vector<ShapeSphere>& shape) {
  std::vector<ClumpSphere> spheres;
  for (const ShapeSphere& s : shape) spheres.push_back({s.centre, s.radius});
  ClumpTemplate t;
  std::string error;
  if (!BuildClumpTemplate(spheres, kDensity, {}, &t, &error)) throw std::runtime_error(error);
  return t.EquivalentVolumeDiameter();
}

// Γ (J/m²) for a cohesion number between two bench spheres: R* = r/2, E* = E / (2(1 − ν²)).
double GammaForCohesion(double coh) {
  const double r_eff = 0.25 * kDiameter, e_eff = kYoungs / (2 * (1 - kPoisson * kPoisson));
  return std::pow(std::pow(coh * kDensity * kGravity, 3) * e_eff * e_eff * std::pow(r_eff, 8), 0.2);
}

Scene BenchScene(const CaseOptions& c) {
  Scene s;
  s.materials = {{"glass", kYoungs, kPoisson, kDensity}};
  s.species = {{"sphere", 0, {}, {}}};
  s.species[0].size.diameter_m = kDiameter;
  int count = c.particles;
  double height = 0.16;  // box height; the bed settles to ≈ 43 mm (spheres), 34 mm (3-rods)
  double margin = 0.001;  // of the pour region from the walls: the enclosing radius
  if (c.clump_spheres > 0) {
    s.species[0].clump_shape = RodClump(c.clump_spheres);
    s.species[0].size.diameter_m = EquivalentDiameter(s.species[0].clump_shape);
    count = static_cast<int>(std::lround(static_cast<double>(c.particles) / c.clump_spheres));
    height = 0.3;  // a loose pour of rods needs more room than one of spheres
    margin = 0.5 * (c.clump_spheres + 1) * 0.5 * kDiameter;
  }
  PairParameters pair;
  pair.sliding_friction = 0.5;
  pair.rolling_friction = 0.1;
  pair.restitution = 0.5;
  pair.interfacial_energy_J_m2 = c.cohesion > 0 ? GammaForCohesion(c.cohesion) : 0;
  s.pair_parameters = {pair};
  s.rolling.name = "epsd2";
  s.walls = BoxInnerFaces("box", {0, 0, 0}, {0.06, 0.06, height}, 0, /*open_top=*/true);
  s.domain_min_m = {0, 0, 0};
  s.domain_max_m = {0.06, 0.06, height + 0.04};
  s.fills.push_back({0, {margin, margin, margin}, {0.06 - margin, 0.06 - margin, height - margin},
                     count, {0, 0, -0.5}});
  s.seed = c.seed;
  s.time.timestep_s = 2.4e-5;
  s.skin_m = 0.0005;
  return s;
}

void PrintResults(const Simulation& sim, const RunSummary& timed, int threads, int64_t steps) {
  const Particles& p = sim.particles();
  double zmax = 0;
  for (const Vec3& x : p.position_m) zmax = std::max(zmax, x.z);
  const double bodies = static_cast<double>(sim.system().BodyCount());
  std::printf("threads: %d\nparticles: %zu\nspheres: %zu\nsteps: %lld\nwall_time_s: %.3f\n",
              threads, sim.system().BodyCount(), p.Size(), static_cast<long long>(steps),
              timed.wall_time_s);
  std::printf("bed_height_m: %.4f\nneighbour_pairs_per_particle: %.2f\n", zmax + 0.001,
              static_cast<double>(sim.neighbours().PairCount()) / p.Size());
  std::printf("contacts_per_particle: %.2f\nneighbour_rebuilds: %llu\n",
              static_cast<double>(sim.ActiveContacts()) / p.Size(),
              static_cast<unsigned long long>(timed.neighbour_rebuilds));
  // Order-independent digest of the final state: equal across thread counts iff bit-identical.
  double digest = 0;
  for (size_t i = 0; i < p.Size(); ++i)
    digest += p.position_m[i].x * (1 + p.id[i] % 7) + p.velocity_m_s[i].z;
  std::printf("state_digest: %a\n", digest);
  std::printf("sphere_steps_per_s: %.0f\n", static_cast<double>(p.Size()) * steps / timed.wall_time_s);
  std::printf("particle_steps_per_s: %.0f\n", bodies * steps / timed.wall_time_s);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"demcal throughput benchmark (see bench/README.md)"};
  app.require_subcommand(1);
  auto* tp = app.add_subcommand("throughput", "time the dense-bed case");
  CaseOptions c;
  int threads = 1;
  int64_t steps = 10000, warmup = 200, settle_steps = 16000;
  std::string bed;
  tp->add_option("--threads", threads, "worker threads");
  tp->add_option("--steps", steps, "timed steps");
  tp->add_option("--warmup-steps", warmup, "untimed steps before timing");
  tp->add_option("--settle-steps", settle_steps, "pour-and-settle steps when no bed is given");
  tp->add_option("--particles", c.particles, "sphere count (with --clump: member spheres)");
  tp->add_option("--clump", c.clump_spheres, "rods of N spheres instead of spheres (0: spheres)")
      ->check(CLI::Range(0, 5));
  tp->add_option("--jkr-cohesion", c.cohesion, "JKR adhesion at this cohesion number (0: off)")
      ->check(CLI::NonNegativeNumber);
  tp->add_option("--bed", bed,
                 "settled bed (a demcal checkpoint of this case without adhesion): loaded if "
                 "present, else written after settling");
  tp->add_option("--seed", c.seed, "random seed of the pour");
  demcal::bench::PourOptions pour;
  CLI::App* pour_command = demcal::bench::AddPourCommand(app, &pour);
  CLI11_PARSE(app, argc, argv);
  if (pour_command->parsed()) return demcal::bench::RunPour(pour);

  const Scene scene = BenchScene(c);
  Simulation sim(scene, {.threads = 0});
  std::string error;
  if (!sim.Initialize(&error)) {
    std::cerr << "error: " << error << "\n";
    return 1;
  }
  if (c.cohesion > 0) {
    std::printf("interfacial_energy_J_m2: %.6g\ncohesion_number: %.6g\n",
                scene.pair_parameters[0].interfacial_energy_J_m2, c.cohesion);
  }
  if (!bed.empty() && std::filesystem::exists(bed)) {
    // The JKR run starts from the same (Hertz-settled) bed: only the contact parameters differ.
    const std::vector<std::string> may_differ =
        c.cohesion > 0 ? std::vector<std::string>{"contact parameters"} : std::vector<std::string>{};
    if (!sim.LoadCheckpoint(bed, &error, may_differ)) {
      std::cerr << "error: " << error << "\n";
      return 1;
    }
  } else {
    std::cerr << "settling " << sim.system().BodyCount() << " particles for " << settle_steps
              << " steps...\n";
    const RunSummary settle = sim.Run(settle_steps * sim.timestep_s());
    std::cerr << "settled: " << settle.BriefReport() << "\n";
    if (!settle.ok()) return 1;
    if (!bed.empty() && !sim.SaveCheckpoint(bed, &error)) std::cerr << "warning: " << error << "\n";
  }
  sim.SetThreads(threads);
  sim.Run(warmup * sim.timestep_s());
  const RunSummary timed = sim.Run(steps * sim.timestep_s());
  if (!timed.ok()) {
    std::cerr << "timed run failed: " << timed.BriefReport() << "\n";
    return 1;
  }
  PrintResults(sim, timed, threads, steps);
  return 0;
}
