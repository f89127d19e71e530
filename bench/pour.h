#pragma once
// demcal_bench pour: the poured heap of bench/bench_cases.h (from the stream, or with
// --particles a filled column thrown onto the base). Times --steps steps from the start of the
// pour and prints where the time went.
#include <CLI/CLI.hpp>

#include <string>

#include "bench/bench_cases.h"

namespace demcal::bench {

struct PourCommand {
  PourOptions pour;
  std::string liggghts_inputs;  // non-empty: write the LIGGGHTS inputs here instead of running
};

CLI::App* AddPourCommand(CLI::App& app, PourCommand* command);
int RunPour(const PourCommand& command);

}  // namespace demcal::bench
