#pragma once
// Checks of what a valid scene would cost, from quantities derived from several fields: the step
// count, the factory batches, the number of snapshots and the memory of the particles. Each value
// can be inside its own range while the combination is nonsense (a batch interval of 1e-30 s
// with a 1e-5 s time step never finishes); these checks refuse it before anything runs, naming
// the field and the limit. The limits and why they have these values: docs/scene_format.md,
// section "Limits".
//
// Thread-safety: free functions, no shared state.
#include <cstdint>
#include <string>

#include "files/scene_file.h"

namespace demcal::workflow {

// 10^9 steps: at the fastest (a few particles, about 1 µs a step) an hour of wall time; a
// bundled scene takes 10^4 to 10^6. More is a unit mistake, not a run.
inline constexpr double kMaxStepsPerRun = 1e9;
// 10^5 VTK snapshots per run: 10^5 files in one folder is already beyond ParaView's comfort.
inline constexpr double kMaxSnapshotsPerRun = 1e5;
// Memory budgeted per sphere: the measured peak resident set of a dense bed (2,356 B/sphere,
// `demcal_bench memory`, docs/performance.md) rounded up; looser packs and clumps need less. A
// budget below the measurement would pass scenes that then run out of memory mid-run.
inline constexpr double kBytesPerSphere = 2400;

// An upper estimate of the spheres the scene holds at its end (listed, filled and inserted by
// factories over the run; clumps count their member spheres).
double EstimatedSpheres(const core::Scene& scene);

// Checks an already IsValid() scene; false with "field 'PATH' ...: ...; allowed ..." in *error.
// `memory_bytes` is the memory available (0: this machine's physical memory).
bool CheckSceneLimits(const SceneFile& file, std::string* error, double memory_bytes = 0);

}  // namespace demcal::workflow
