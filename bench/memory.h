#pragma once
// demcal_bench memory: the dense bed of bench/bench_cases.h run --settle-steps steps, then the
// heap bytes of the engine's arrays (counted from their capacities: core/math/heap_bytes.h) per
// sphere, per listed pair and per contact, with the allocator's bytes in use and the peak
// resident set as cross-checks. docs/performance.md turns them into the largest bed or heap a
// node holds.
#include <CLI/CLI.hpp>

#include <string>

#include "bench/bench_cases.h"

namespace demcal::bench {

struct MemoryCommand {
  BedOptions bed;
  int64_t settle_steps = 2000;
  int threads = 0;
  std::string checkpoint;  // of this case (demcal_bench throughput --bed) to start from
};

CLI::App* AddMemoryCommand(CLI::App& app, MemoryCommand* command);
int RunMemory(const MemoryCommand& command);

}  // namespace demcal::bench
