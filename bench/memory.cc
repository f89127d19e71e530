#include "bench/memory.h"

#include <malloc.h>

#include <cstdio>
#include <fstream>
#include <iostream>
#include <string>

#include "core/simulation/simulation.h"

namespace demcal::bench {
namespace {

// A "Vm...: N kB" line of /proc/self/status, in bytes (0 where unreadable).
double ProcStatusBytes(const std::string& key) {
  std::ifstream in("/proc/self/status");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind(key + ":", 0) == 0) return 1024.0 * std::stod(line.substr(key.size() + 1));
  return 0;
}

}  // namespace

CLI::App* AddMemoryCommand(CLI::App& app, MemoryCommand* command) {
  auto* c = app.add_subcommand("memory", "heap bytes per sphere and per contact of the dense bed");
  c->add_option("--particles", command->bed.particles,
                "sphere count (with --clump: member spheres)")
      ->check(CLI::PositiveNumber);
  c->add_option("--clump", command->bed.clump_spheres, "rods of N spheres (0: spheres)")
      ->check(CLI::Range(0, 5));
  c->add_option("--settle-steps", command->settle_steps, "steps to run before counting")
      ->check(CLI::NonNegativeNumber);
  c->add_option("--threads", command->threads, "worker threads (0: all cores)")
      ->check(CLI::NonNegativeNumber);
  c->add_option("--bed", command->checkpoint,
                "start from this checkpoint of the case (a settled bed)")
      ->check(CLI::ExistingFile);
  return c;
}

int RunMemory(const MemoryCommand& command) {
  const core::Scene scene = DenseBedScene(command.bed);
  core::Simulation sim(scene, {.threads = command.threads});
  std::string error;
  if (!sim.Initialize(&error)) {
    std::cerr << "error: " << error << "\n";
    return 1;
  }
  if (!command.checkpoint.empty() && !sim.LoadCheckpoint(command.checkpoint, &error)) {
    std::cerr << "error: " << error << "\n";
    return 1;
  }
  const core::RunSummary run = sim.Run(command.settle_steps * sim.timestep_s());
  if (!run.ok()) {
    std::cerr << "run failed: " << run.BriefReport() << "\n";
    return 1;
  }
  const core::HeapBytes heap = sim.Heap();
  const double spheres = static_cast<double>(sim.particles().Size());
  const double bodies = static_cast<double>(sim.system().BodyCount());
  const double pairs = static_cast<double>(sim.neighbours().PairCount());
  const double contacts = static_cast<double>(sim.ActiveContacts());
  const struct mallinfo2 m = mallinfo2();
  std::printf("spheres: %.0f\nbodies: %.0f\nsteps: %lld\nneighbour_rebuilds: %llu\n", spheres,
              bodies, static_cast<long long>(run.steps),
              static_cast<unsigned long long>(run.neighbour_rebuilds));
  std::printf("neighbour_pairs_per_sphere: %.3f\ncontacts_per_sphere: %.3f\n", pairs / spheres,
              contacts / spheres);
  std::printf("heap_per_particle_arrays_B: %zu\nheap_per_pair_arrays_B: %zu\nheap_other_B: %zu\n",
              heap.per_particle, heap.per_pair, heap.other);
  std::printf("bytes_per_sphere_particle_arrays_B: %.1f\nbytes_per_listed_pair_B: %.1f\n",
              heap.per_particle / spheres, heap.per_pair / pairs);
  if (contacts > 0) std::printf("bytes_per_contact_B: %.1f\n", heap.per_pair / contacts);
  std::printf("bytes_per_sphere_all_in_B: %.1f\n", heap.Total() / spheres);
  // Cross-checks of the count: the allocator's bytes in use and the process' peak resident set.
  std::printf("malloc_in_use_B: %zu\nmalloc_in_use_per_sphere_B: %.1f\n", m.uordblks + m.hblkhd,
              (m.uordblks + m.hblkhd) / spheres);
  std::printf("peak_resident_B: %.0f\npeak_resident_per_sphere_B: %.1f\n",
              ProcStatusBytes("VmHWM"), ProcStatusBytes("VmHWM") / spheres);
  return 0;
}

}  // namespace demcal::bench
