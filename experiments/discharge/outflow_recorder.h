#pragma once
// OutflowRecorder: the mass that has left a funnel, per species, sampled over time. A grain
// counts once, the first time its centre is seen below the orifice plane (z < plane_z_m), so
// grains that bounce back up on the catch heap are not counted twice. Each Sample() also tells
// what is still above the plane (the hopper's content), which decides when the hopper is empty.
//
// Not thread-safe; one recorder per simulation.
//
//   OutflowRecorder rec(model.species.size(), 0.0);
//   rec.Sample(sim);                       // every sample interval
//   if (rec.remaining_count() == 0) stop;  // empty
//   AnalyseDischarge(rec.samples(), t0, options);
#include <cstdint>
#include <vector>

#include "core/simulation/simulation.h"
#include "objectives/metrics/discharge_metrics.h"

namespace demcal::objectives {

class OutflowRecorder {
 public:
  OutflowRecorder(size_t species_count, double plane_z_m);

  // Counts the grains newly below the plane and appends a sample at the simulation's time.
  void Sample(const core::Simulation& sim);

  const std::vector<OutflowSample>& samples() const { return samples_; }
  double total_out_kg() const { return total_out_kg_; }
  // Grains (spheres) and their mass above the plane at the last sample.
  int64_t remaining_count() const { return remaining_count_; }
  double remaining_kg() const { return remaining_kg_; }

 private:
  double plane_z_m_;
  std::vector<double> cumulative_kg_;  // per species
  std::vector<char> counted_;          // by particle id
  std::vector<OutflowSample> samples_;
  double total_out_kg_ = 0;
  int64_t remaining_count_ = 0;
  double remaining_kg_ = 0;
};

}  // namespace demcal::objectives
