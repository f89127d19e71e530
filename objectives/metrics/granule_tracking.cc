#include "objectives/metrics/granule_tracking.h"

#include <algorithm>
#include <cmath>

namespace demcal::objectives {
namespace {

int IndexOfId(const Snapshot& snapshot, int64_t id) {
  for (size_t i = 0; i < snapshot.grains.size(); ++i)
    if (snapshot.grains[i].id == id) return static_cast<int>(i);
  return -1;
}

std::optional<double> SurfaceNearGrain(const Snapshot& snapshot, int index,
                                       const SurfaceOptions& options) {
  const Grain& g = snapshot.grains[index];
  const double column_width = options.column_width_diameters * 2 * g.radius_m;
  return SurfaceHeightAt(snapshot, g.position_m.x, column_width, options.max_surface_speed_m_s,
                         index);
}

}  // namespace

double GranuleSample::SpecificKineticEnergyJPerKg() const { return 0.5 * Norm2(velocity_m_s); }
double GranuleSample::SpeedMS() const { return Norm(velocity_m_s); }

std::optional<double> SurfaceHeightAt(const Snapshot& snapshot, double x_m, double column_width_m,
                                      double max_surface_speed_m_s, int exclude_grain) {
  std::optional<double> height;
  for (const SurfaceSphere& sphere : snapshot.spheres) {
    if (sphere.grain == exclude_grain) continue;
    if (std::abs(sphere.position_m.x - x_m) > column_width_m / 2) continue;
    if (Norm(snapshot.grains[sphere.grain].velocity_m_s) > max_surface_speed_m_s) continue;
    const double top = sphere.position_m.z + sphere.radius_m;
    height = height ? std::max(*height, top) : top;
  }
  return height;
}

std::vector<GranuleTrack> TrackGranules(const std::vector<Snapshot>& snapshots,
                                        const std::vector<int64_t>& ids,
                                        const SurfaceOptions& options) {
  std::vector<GranuleTrack> tracks;
  for (int64_t id : ids) tracks.push_back({id, 0, {}});
  for (const Snapshot& snapshot : snapshots) {
    for (GranuleTrack& track : tracks) {
      const int index = IndexOfId(snapshot, track.id);
      if (index < 0) continue;
      const Grain& g = snapshot.grains[index];
      track.species = g.species;
      GranuleSample sample{snapshot.time_s, g.position_m, g.velocity_m_s, g.radius_m, false, 0};
      if (const auto surface = SurfaceNearGrain(snapshot, index, options)) {
        sample.has_surface = true;
        sample.surface_height_m = *surface;
      }
      track.samples.push_back(sample);
    }
  }
  return tracks;
}

std::optional<int> FirstSpeedDropIndex(const GranuleTrack& track, const ImpactOptions& options) {
  double peak = 0;
  for (size_t i = 0; i < track.samples.size(); ++i) {
    const double speed = track.samples[i].SpeedMS();
    if (peak >= options.min_peak_speed_m_s && speed < (1 - options.speed_drop_fraction) * peak)
      return static_cast<int>(i);
    peak = std::max(peak, speed);
  }
  return std::nullopt;
}

std::optional<int> FirstSurfaceApproachIndex(const GranuleTrack& track,
                                             const ImpactOptions& options) {
  for (size_t i = 0; i < track.samples.size(); ++i) {
    const GranuleSample& s = track.samples[i];
    const double gap = s.position_m.z - s.radius_m - s.surface_height_m;
    if (s.has_surface && gap <= options.approach_gap_diameters * 2 * s.radius_m)
      return static_cast<int>(i);
  }
  return std::nullopt;
}

std::optional<Penetration> PenetrationDepth(const Snapshot& snapshot, int64_t id,
                                            const SurfaceOptions& options, std::string* error) {
  const int index = IndexOfId(snapshot, id);
  if (index < 0) {
    if (error) *error = "penetration: grain " + std::to_string(id) + " is not in the snapshot";
    return std::nullopt;
  }
  const auto surface = SurfaceNearGrain(snapshot, index, options);
  if (!surface) {
    if (error) *error = "penetration: no surface sphere near grain " + std::to_string(id);
    return std::nullopt;
  }
  const Grain& g = snapshot.grains[index];
  Penetration p;
  p.surface_height_m = *surface;
  p.depth_m = *surface - g.position_m.z;
  p.depth_diameters = g.radius_m > 0 ? p.depth_m / (2 * g.radius_m) : 0.0;
  return p;
}

}  // namespace demcal::objectives
