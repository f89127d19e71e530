#pragma once
// GranuleRecorder: follows a few granules of one species through a run (Alizadeh et al. 2018,
// section 3.4, Figs. 17–19). Granules are picked as they enter the run: of those of `species`
// inserted after start_time_s, every stride-th from a seed-chosen offset, up to `count` — so the
// choice is deterministic from the seed and spread over the rest of the pour. At every Observe
// the followed granules below `below_z_m` (under the funnel, where the heap surface is not
// confused with the slow grains inside the funnel) get one sample (position, velocity, local
// heap surface height; granule_tracking.h).
//
// Usage (from a run's per-check hook, every few ms of simulated time):
//   GranuleRecorder recorder(options, seed);
//   hooks.on_check = [&](const core::Simulation& sim) { recorder.Observe(sim); };
//   for (const GranuleTrack& t : recorder.tracks()) ...
#include <cstdint>
#include <vector>

#include "core/simulation/simulation.h"
#include "objectives/metrics/granule_tracking.h"

namespace demcal::objectives {

struct GranuleRecorderOptions {
  int species = 0;
  int count = 20;
  double start_time_s = 0;
  int stride = 1;  // ≥ 1
  double below_z_m = 1e9;
  SurfaceOptions surface;
};

class GranuleRecorder {
 public:
  GranuleRecorder(const GranuleRecorderOptions& options, uint64_t seed);

  void Observe(const core::Simulation& sim);

  const std::vector<int64_t>& ids() const { return ids_; }
  // One track per picked granule, in the order picked.
  const std::vector<GranuleTrack>& tracks() const { return tracks_; }

 private:
  void Pick(const Snapshot& snapshot);

  GranuleRecorderOptions options_;
  int offset_ = 0;          // in [0, stride)
  int64_t candidates_ = 0;  // granules of the species seen after start_time_s
  int64_t last_seen_id_ = -1;
  std::vector<int64_t> ids_;
  std::vector<GranuleTrack> tracks_;
};

// Every how many granules of `species` one is picked so that `count` spread over the feed after
// start_fraction of it: (expected granules after the start) / count, at least 1.
int TrackingStride(const core::Scene& model, double feed_mass_kg, double species_mass_fraction,
                   int species, double start_fraction, int count);

}  // namespace demcal::objectives
