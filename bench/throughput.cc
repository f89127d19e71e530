// demcal_bench throughput: the side-by-side case of bench/README.md (LIGGGHTS reference case):
// by default 20,000 spheres (--particles: any count; bench/bench_cases.h sizes the box),
// d = 2 mm, ρ = 2500 kg/m³, E = 5 MPa, ν = 0.25, e = 0.5, μs = 0.5, μr = 0.1
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

#include "bench/bench_cases.h"
#include "bench/liggghts_inputs.h"
#include "bench/memory.h"
#include "bench/pour.h"
#include "bench/state_digest.h"
#include "core/simulation/simulation.h"

using namespace demcal::core;
using demcal::bench::BedOptions;

namespace {

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
  std::printf("state_digest: %a\n", demcal::bench::StateDigest(p));
  std::printf("sphere_steps_per_s: %.0f\n", static_cast<double>(p.Size()) * steps / timed.wall_time_s);
  std::printf("particle_steps_per_s: %.0f\n", bodies * steps / timed.wall_time_s);
  std::printf("phases: %s\n", timed.phases.Report().c_str());
  std::printf("sweep balance: %s\n", timed.sweep_balance.Report().c_str());
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"demcal throughput benchmark (see bench/README.md)"};
  app.require_subcommand(1);
  auto* tp = app.add_subcommand("throughput", "time the dense-bed case");
  BedOptions c;
  int threads = 1, balance_probe = 0;
  int64_t steps = 10000, warmup = 200, settle_steps = 16000;
  std::string bed, save_bed, liggghts_inputs;
  tp->add_option("--threads", threads, "worker threads");
  tp->add_option("--balance-probe", balance_probe,
                 "timed steps with the sweep in N chunks run one after another on one thread: "
                 "the balance N threads would see (Simulation::Options::balance_probe_chunks)")
      ->check(CLI::NonNegativeNumber);
  tp->add_option("--steps", steps, "timed steps");
  tp->add_option("--warmup-steps", warmup, "untimed steps before timing");
  tp->add_option("--settle-steps", settle_steps, "pour-and-settle steps when no bed is given");
  tp->add_option("--particles", c.particles, "sphere count (with --clump: member spheres)")
      ->check(CLI::PositiveNumber);
  tp->add_option("--clump", c.clump_spheres, "rods of N spheres instead of spheres (0: spheres)")
      ->check(CLI::Range(0, 5));
  tp->add_option("--jkr-cohesion", c.cohesion, "JKR adhesion at this cohesion number (0: off)")
      ->check(CLI::NonNegativeNumber);
  tp->add_option("--bed", bed,
                 "settled bed (a demcal checkpoint of this case without adhesion): loaded if "
                 "present, else written after settling");
  tp->add_option("--save-bed", save_bed,
                 "after the timed steps, write the state as a bed for --bed (e.g. one whose "
                 "particle order this build chose)");
  tp->add_option("--seed", c.seed, "random seed of the pour");
  tp->add_option("--liggghts-inputs", liggghts_inputs,
                 "write DIR/initial.data and DIR/case.vars for LIGGGHTS and exit: the unsettled "
                 "pack, or the --bed if it exists");
  demcal::bench::PourCommand pour;
  CLI::App* pour_command = demcal::bench::AddPourCommand(app, &pour);
  demcal::bench::MemoryCommand memory;
  CLI::App* memory_command = demcal::bench::AddMemoryCommand(app, &memory);
  CLI11_PARSE(app, argc, argv);
  if (pour_command->parsed()) return demcal::bench::RunPour(pour);
  if (memory_command->parsed()) return demcal::bench::RunMemory(memory);

  const Scene scene = demcal::bench::DenseBedScene(c);
  Simulation sim(scene, {.threads = 0});
  std::string error;
  if (!sim.Initialize(&error)) {
    std::cerr << "error: " << error << "\n";
    return 1;
  }
  // Without a settled bed to load, the LIGGGHTS inputs are the unsettled pack (LIGGGHTS then
  // settles it itself, in.settle_data); with one, the bed as loaded, so that both codes time
  // the very same state (in.settle_data with settle_steps 0 only converts it).
  const bool bed_exists = !bed.empty() && std::filesystem::exists(bed);
  auto write_liggghts_inputs = [&] {
    const demcal::bench::LiggghtsVars vars = {
        {"box_xy", demcal::bench::DenseBedBox(c).side_m},
        {"nparticles", static_cast<double>(sim.particles().Size())}};
    if (demcal::bench::WriteLiggghtsInputs(liggghts_inputs, sim.particles(), scene.domain_min_m,
                                           scene.domain_max_m, vars, &error))
      return 0;
    std::cerr << "error: " << error << "\n";
    return 1;
  };
  if (!liggghts_inputs.empty() && !bed_exists) return write_liggghts_inputs();
  if (c.cohesion > 0) {
    std::printf("interfacial_energy_J_m2: %.6g\ncohesion_number: %.6g\n",
                scene.pair_parameters[0].interfacial_energy_J_m2, c.cohesion);
  }
  if (bed_exists) {
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
  if (!liggghts_inputs.empty()) return write_liggghts_inputs();
  sim.SetThreads(threads);
  sim.SetBalanceProbe(balance_probe);
  sim.Run(warmup * sim.timestep_s());
  const RunSummary timed = sim.Run(steps * sim.timestep_s());
  if (!timed.ok()) {
    std::cerr << "timed run failed: " << timed.BriefReport() << "\n";
    return 1;
  }
  PrintResults(sim, timed, threads, steps);
  if (!save_bed.empty() && !sim.SaveCheckpoint(save_bed, &error)) {
    std::cerr << "error: " << error << "\n";
    return 1;
  }
  return 0;
}
