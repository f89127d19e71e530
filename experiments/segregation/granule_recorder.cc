#include "experiments/segregation/granule_recorder.h"

#include <algorithm>
#include <cmath>

#include "core/math/random.h"
#include "core/math/seed_streams.h"

namespace demcal::objectives {

GranuleRecorder::GranuleRecorder(const GranuleRecorderOptions& options, uint64_t seed)
    : options_(options) {
  options_.stride = std::max(1, options_.stride);
  offset_ = static_cast<int>(core::DeriveSeed(seed, core::kGranuleSampleStream) % options_.stride);
}

void GranuleRecorder::Pick(const Snapshot& snapshot) {
  // Grains are in id order and ids grow with insertion: the new ones follow last_seen_id_.
  for (const Grain& g : snapshot.grains) {
    if (g.id <= last_seen_id_) continue;
    last_seen_id_ = g.id;
    if (g.species != options_.species || snapshot.time_s < options_.start_time_s) continue;
    const int64_t k = candidates_++;
    if (static_cast<int>(ids_.size()) < options_.count && k % options_.stride == offset_) {
      ids_.push_back(g.id);
      tracks_.push_back({g.id, g.species, {}});
    }
  }
}

void GranuleRecorder::Observe(const core::Simulation& sim) {
  if (options_.count <= 0) return;
  const Snapshot snapshot = TakeSnapshot(sim);
  Pick(snapshot);
  if (ids_.empty()) return;
  const Snapshot below = Crop(snapshot, {-1e9, -1e9, -1e9}, {1e9, 1e9, options_.below_z_m});
  const std::vector<GranuleTrack> now = TrackGranules({below}, ids_, options_.surface);
  for (size_t k = 0; k < now.size(); ++k)
    for (const GranuleSample& s : now[k].samples) tracks_[k].samples.push_back(s);
}

int TrackingStride(const core::Scene& model, double feed_mass_kg, double species_mass_fraction,
                   int species, double start_fraction, int count) {
  const core::Species& sp = model.species[species];
  const double grain_mass = model.materials[sp.material].density_kg_m3 * sp.size.MeanVolume();
  if (count <= 0 || !(grain_mass > 0)) return 1;
  const double expected = feed_mass_kg * species_mass_fraction * (1 - start_fraction) / grain_mass;
  return std::max(1, static_cast<int>(std::floor(expected / count)));
}

}  // namespace demcal::objectives
