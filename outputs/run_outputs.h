#pragma once
// RunOutputs: the files a `demcal simulate` run writes into its output directory DIR.
//   DIR/vtk/particles_NNNNNN.vtk   snapshots (core/io/vtk_writer.h): the initial state, one
//                                  every round(vtk_interval_s / Δt) steps, and the final state
//   DIR/vtk/particles.vtk.series   ParaView's index of the snapshots with their times
//   DIR/final_particles.csv        the final state, one row per sphere (core/io/csv_writer.h)
//   DIR/final_clumps.csv           the final state of the clumps, one row each (only if any)
//   DIR/scene.json                 a byte-for-byte copy of the scene file, so that DIR alone
//                                  reproduces the run
//   DIR/checkpoint.bin             the latest checkpoint (core::Simulation::SaveCheckpoint),
//                                  when asked for; replaced atomically (temporary file + rename)
// A restarted run (demcal simulate --restart) writing into the DIR of the run it continues keeps
// that run's snapshots up to the restart time and numbers its own after them.
// summary.json is written by the caller (summary_json.h) with Describe() as its "outputs".
//
// Thread-safety: single-threaded use; WriteSnapshot may be called from a Simulation observer.
//
// Usage:
//   RunOutputs outputs(dir, file.output);
//   if (!outputs.Prepare(&error)) ...;
//   outputs.WriteSnapshot(sim, &error);  ...  outputs.WriteFinal(sim, &error);
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>

#include "files/scene_file.h"
#include "core/io/vtk_writer.h"
#include "core/simulation/simulation.h"

namespace demcal::workflow {

class RunOutputs {
 public:
  RunOutputs(std::string directory, OutputSettings settings);

  // Creates DIR and DIR/vtk if needed.
  bool Prepare(std::string* error);
  // Copies the scene file to DIR/scene.json (nothing to do if it is that file already).
  bool CopyScene(const std::string& scene_path, std::string* error);
  // For a run restarted at `time_s`: continues the VTK series found in DIR (if any) with its
  // snapshots up to `time_s`, and writes a snapshot of the restored state unless the series
  // already has one at exactly that time.
  bool ResumeFrom(const core::Simulation& sim, std::string* error);
  // Steps between periodic snapshots for a time step; 0 when only initial and final are kept.
  int64_t SnapshotEverySteps(double timestep_s) const;
  // Writes a snapshot of the current state (and refreshes the series index).
  bool WriteSnapshot(const core::Simulation& sim, std::string* error);
  // Writes the final snapshot (unless the current step already has one) and the CSV tables.
  bool WriteFinal(const core::Simulation& sim, std::string* error);

  // Writes DIR/checkpoint.bin atomically (Simulation::SaveCheckpoint: temporary, fsync,
  // rename), so a crash while writing leaves the previous checkpoint intact.
  bool WriteCheckpoint(const core::Simulation& sim, std::string* error);

  std::string SummaryPath() const { return directory_ + "/summary.json"; }
  std::string CsvPath() const { return directory_ + "/final_particles.csv"; }
  std::string ClumpCsvPath() const { return directory_ + "/final_clumps.csv"; }
  std::string CheckpointPath() const;
  // The outputs written so far, with paths relative to DIR, for summary.json.
  nlohmann::ordered_json Describe() const;

 private:
  std::string directory_;
  OutputSettings settings_;
  core::io::VtkSeries series_;
  int64_t last_snapshot_step_ = -1;
  bool csv_written_ = false;
  bool clump_csv_written_ = false;
  bool scene_copied_ = false;
  double checkpoint_time_s_ = -1;  // simulated time of the last checkpoint written (< 0: none)
};

}  // namespace demcal::workflow
