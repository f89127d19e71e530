#pragma once
// RunHooks: what a virtual experiment reports while it runs (progress, periodic checks, the final
// state), so apps can show progress and write snapshots without the experiment knowing about
// files, and how many threads its one simulation may use. Every hook may be empty; they are
// called from the thread that runs the simulation.
//
//   RunHooks hooks;
//   hooks.progress = [](double t, double end) { std::printf("%.2f of %.2f s\n", t, end); };
//   RunAor(model, settings, seed, hooks);
#include <functional>

#include "core/simulation/simulation.h"
#include "objectives/common/settled_run.h"

namespace demcal::objectives {

struct RunHooks {
  ProgressCallback progress;                                // (simulated s, expected end s)
  std::function<void(const core::Simulation&)> on_check;   // every settle or sample check
  std::function<void(const core::Simulation&)> on_finish;  // once, at the end
  // Threads of the simulation (>= 1). Results are bit-identical for any count (core/simulation/simulation.h),
  // so this is a scheduling choice: 1 when replicates fill the cores, more when they do not.
  int threads = 1;
};

}  // namespace demcal::objectives
