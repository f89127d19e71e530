#include "bench/pour.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>

#include "bench/liggghts_inputs.h"
#include "bench/state_digest.h"
#include "core/simulation/simulation.h"

namespace demcal::bench {

CLI::App* AddPourCommand(CLI::App& app, PourCommand* command) {
  PourOptions* o = &command->pour;
  auto* c = app.add_subcommand("pour", "time the poured heap on a frozen base");
  c->add_option("--particles", o->particles,
                "spheres of a column filled at t = 0 above the base (0: the stream)")
      ->check(CLI::NonNegativeNumber);
  c->add_option("--liggghts-inputs", command->liggghts_inputs,
                "write DIR/initial.data and DIR/case.vars of this case for LIGGGHTS and exit");
  c->add_option("--threads", o->threads, "worker threads");
  c->add_option("--balance-probe", o->balance_probe_chunks,
                "the sweep in N chunks run one after another on one thread: the balance N "
                "threads would see (Simulation::Options::balance_probe_chunks)")
      ->check(CLI::NonNegativeNumber);
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

int RunPour(const PourCommand& command) {
  const PourOptions& o = command.pour;
  const core::Scene scene = PourScene(o);
  core::Simulation sim(scene, {.threads = o.threads,
                               .exclude_fixed_pairs = !o.keep_fixed_pairs,
                               .neighbour_refresh_fraction = o.refresh_fraction,
                               .balance_probe_chunks = o.balance_probe_chunks});
  std::string error;
  if (!sim.Initialize(&error)) {
    std::cerr << "error: " << error << "\n";
    return 1;
  }
  const size_t base = scene.particles.size();
  if (!command.liggghts_inputs.empty()) {
    const LiggghtsVars vars = {{"half", scene.domain_max_m.x},
                               {"top", scene.domain_max_m.z - 0.02},
                               {"nparticles", static_cast<double>(o.particles)}};
    if (!WriteLiggghtsInputs(command.liggghts_inputs, sim.particles(), scene.domain_min_m,
                             scene.domain_max_m, vars, &error)) {
      std::cerr << "error: " << error << "\n";
      return 1;
    }
    return 0;
  }
  // No observer: one called every step would keep the second half kick from joining the next
  // step's first (Simulation::Run), a pass over the spheres a user's run does not make.
  const core::RunSummary run = sim.Run(o.steps * sim.timestep_s());
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
              run.rebuild_search.searched / std::max<double>(1, run.neighbour_rebuilds),
              run.rebuild_search.moving / std::max<double>(1, run.neighbour_rebuilds));
  // Moving spheres (those present at the end) × steps / s: the figure scaling.sh compares.
  std::printf("particle_steps_per_s: %.0f\n",
              static_cast<double>(spheres - base) * run.steps / run.wall_time_s);
  std::printf("state_digest: %a\n", StateDigest(sim.particles()));
  std::printf("phases: %s\n", run.phases.Report().c_str());
  std::printf("sweep balance: %s\n", run.sweep_balance.Report().c_str());
  return 0;
}

}  // namespace demcal::bench
