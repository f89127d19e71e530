#pragma once
// RunRecord and summary.json: what a `demcal simulate` run was asked to do and how it ended.
// Written for every run that got as far as reading its command line, including runs whose
// scene was invalid (termination "invalid_scene") or whose simulation failed, so scripts and
// the calibrator can always read the outcome from one place. Keys are listed in docs/cli.md.
//
// Usage:
//   RunRecord r;  r.scene_path = ...;  r.summary = sim.Run(...);
//   WriteRunSummaryJson(outputs.SummaryPath(), r, &error);
#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/insertion/factory.h"
#include "core/simulation/run_summary.h"
#include "core/insertion/sink.h"
#include "core/walls/walls.h"

namespace demcal::workflow {

inline constexpr const char* kRunSummaryFormat = "demcal-run-summary/1";

// The load on one wall at the end of the run (see core::Simulation::WallLoads).
struct NamedWallLoad {
  std::string name;
  core::WallLoad load;
};

struct RunRecord {
  std::string scene_path;
  std::string scene_description;
  std::optional<uint64_t> seed;  // unknown if the scene could not be read
  std::optional<double> requested_duration_s;
  int threads_requested = 0;  // 0: all cores
  int threads_used = 0;
  core::RunSummary summary;                    // termination, message, steps, times, energy
  double setup_wall_time_s = 0;                // scene loading, particle placement, first forces
  double total_wall_time_s = 0;                // the whole command, outputs included
  std::vector<core::FactoryReport> factories;  // one per scene factory
  std::vector<std::string> factory_warnings;   // Simulation::FactoryRateWarnings at the end
  std::vector<NamedWallLoad> wall_loads;       // one per wall, at the end of the run
  std::vector<core::SinkReport> sinks;         // one per sink, then "domain" (if any sinks)
  std::vector<std::string> species_names;      // to name the per-species sink tallies
  struct Restart {
    std::string checkpoint_path;  // as given to --restart
    double time_s = 0;            // simulated time of the checkpoint
    int64_t steps = 0;            // steps taken before the checkpoint
  };
  std::optional<Restart> restarted_from;  // set if the run continued a checkpoint
  std::string output_error;                    // non-empty if an output file could not be written
  // A rejected run: the earlier run's outputs it moved into previous_run/ (earlier_outputs.h).
  std::vector<std::string> earlier_outputs_moved;
  nlohmann::ordered_json outputs = nlohmann::ordered_json::object();  // RunOutputs::Describe()
};

nlohmann::ordered_json RunRecordToJson(const RunRecord& record);
bool WriteRunSummaryJson(const std::string& path, const RunRecord& record, std::string* error);

}  // namespace demcal::workflow
