#pragma once
// MassFlowLog: mass-vs-time of a `demcal simulate` run, DIR/mass_flow.csv, one row every
// output.mass_flow_interval_s of simulated time (and the initial and final states). Columns,
// units in every name (species and sink names as in the scene):
//   time_s
//   sink.<sink>.<species>.removed_count      particles a sink removed so far (core/insertion/sink.h;
//   sink.<sink>.<species>.removed_mass_kg    "domain" is the implicit domain sink)
//   plane.<plane>.<species>.mass_beyond_kg   mass whose centre is beyond a counting plane now
//                                            (output.mass_flow_planes; nothing is removed)
//   factory.<factory>.inserted_mass_kg       what a factory has inserted so far
// The discharged mass of a silo is a sink's removed mass (or the mass beyond a plane under the
// orifice); the flow rate is its slope. Rows are kept in memory and the whole file is written
// atomically with every checkpoint and at the end (Flush), so a killed run leaves a complete
// file that matches its last checkpoint; a restarted run keeps the rows up to its restart time.
//
// Thread-safety: single-threaded (a Simulation observer).
#include <string>
#include <vector>

#include "core/simulation/simulation.h"
#include "files/scene_file.h"

namespace demcal::workflow {

class MassFlowLog {
 public:
  MassFlowLog(std::string path, const OutputSettings& settings);

  bool enabled() const { return interval_s_ > 0; }
  // Steps between rows for a time step (0: disabled).
  int64_t EverySteps(double timestep_s) const;
  // For a restarted run: keeps the rows of an existing file (same header) up to time_s.
  bool ResumeFrom(const core::Simulation& sim, std::string* error);
  // Appends the current state as a row (unless this time already has one).
  void Record(const core::Simulation& sim);
  // Writes the file (atomically) with the rows so far; no-op when disabled.
  bool Flush(const core::Simulation& sim, std::string* error) const;
  const std::string& path() const { return path_; }
  size_t rows() const { return rows_.size(); }

 private:
  std::string Header(const core::Simulation& sim) const;
  std::vector<double> Row(const core::Simulation& sim) const;

  std::string path_;
  double interval_s_ = 0;
  std::vector<core::SinkSpec> planes_;
  std::vector<std::vector<double>> rows_;
};

}  // namespace demcal::workflow
