#pragma once
// Granule tracking (Alizadeh et al. 2018, section 3.4, Figs. 17–19): selected grains followed
// through a time series of snapshots — their specific kinetic energy ½v² (J/kg) against time
// (Fig. 19), the moment they first hit the heap, and how deep below the local heap surface they
// end up (Figs. 17–18).
//
// Heap surface height at x: the highest sphere top (z + r) among the SurfaceSpheres whose centre
// lies in a column of width `column_width_diameters` × the tracked grain's diameter around x. The
// tracked grain itself is left out, and so are grains faster than `max_surface_speed_m_s`: the
// falling stream above the heap is not its surface (grains avalanching on the surface move at a
// few 0.1 m/s, grains falling from the funnel at ~1 m/s or more).
//
// Penetration depth: local surface height − the grain's centre height; about −r for a grain lying
// on the surface, > r once it is buried (compare in diameters, `depth_diameters`).
//
// Pure functions on snapshots; units SI. Usage:
//   auto tracks = TrackGranules(snapshots, {ep_id_1, ep_id_2}, {});
//   auto impact = FirstSpeedDropIndex(tracks[0], {});
//   auto depth = PenetrationDepth(snapshots.back(), ep_id_1, {});
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "objectives/common/snapshot.h"

namespace demcal::objectives {

struct SurfaceOptions {
  double column_width_diameters = 2.0;  // width of the column around x, in tracked-grain diameters
  double max_surface_speed_m_s = 0.5;   // faster grains are in flight, not part of the surface
};

struct GranuleSample {
  double time_s = 0;
  Vec3 position_m;
  Vec3 velocity_m_s;
  double radius_m = 0;
  bool has_surface = false;                    // false: no slow sphere in the column
  double surface_height_m = 0;                 // heap surface at the grain's x in this snapshot
  double SpecificKineticEnergyJPerKg() const;  // ½ v²
  double SpeedMS() const;
};

struct GranuleTrack {
  int64_t id = 0;
  int species = 0;
  std::vector<GranuleSample> samples;  // in snapshot order; snapshots without the id are skipped
};

// Heap surface height at x (see above), excluding the grain with index `exclude_grain` (−1: none).
std::optional<double> SurfaceHeightAt(const Snapshot& snapshot, double x_m, double column_width_m,
                                      double max_surface_speed_m_s, int exclude_grain = -1);

// One track per id (in the order given; an id never seen gives a track without samples).
std::vector<GranuleTrack> TrackGranules(const std::vector<Snapshot>& snapshots,
                                        const std::vector<int64_t>& ids,
                                        const SurfaceOptions& options);

struct ImpactOptions {
  double min_peak_speed_m_s = 0.3;      // the grain must have been falling this fast before
  double speed_drop_fraction = 0.5;     // impact = speed below (1 − this) × the running peak
  double approach_gap_diameters = 1.0;  // surface approach: grain bottom within this of surface
};

// Index of the first sample after which the speed has fallen sharply: speed < (1 − drop) × the
// highest speed so far, once that peak exceeded min_peak_speed. nullopt if it never happens.
std::optional<int> FirstSpeedDropIndex(const GranuleTrack& track, const ImpactOptions& options);

// Index of the first sample where the grain's bottom (z − r) comes within approach_gap_diameters
// diameters of the surface height. nullopt if it never happens.
std::optional<int> FirstSurfaceApproachIndex(const GranuleTrack& track,
                                             const ImpactOptions& options);

struct Penetration {
  double surface_height_m = 0;
  double depth_m = 0;          // surface height − centre height
  double depth_diameters = 0;  // depth_m / (2 r)
};

// Penetration of grain `id` below the local surface in `snapshot` (e.g. the last one). nullopt
// and a message if the id is absent or no surface sphere lies in its column.
std::optional<Penetration> PenetrationDepth(const Snapshot& snapshot, int64_t id,
                                            const SurfaceOptions& options, std::string* error);

}  // namespace demcal::objectives
