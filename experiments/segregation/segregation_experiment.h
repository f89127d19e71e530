#pragma once
// Segregation-heap experiment (Alizadeh et al. 2018, sections 2.1, 2.6, 2.8, 3.1–3.4): a mixture
// (the paper: BP, TAED and EP, Table 1) is generated homogeneously at a constant mass rate above a
// funnel, runs through it into a pseudo-2D box and forms a heap on a rough (glued) base. When the
// heap has settled the run reports the segregation indices of the heap (front face, back face,
// every depth layer, whole heap; heap_segregation.h), the mixture's repose angle, the funnel
// discharge time, and the histories of a few tracked granules of the minor species (impact on
// the heap and penetration below its surface, Figs. 17–19).
//
// Geometry (z up, floor at z = 0; see docs/experiments/segregation.md for the assumptions):
//   box     x ∈ [0, width], y ∈ [0, depth]; its front (y = 0) and back (y = depth) planes are
//           infinite, so they also slice the funnel: the funnel is a conical hopper cut to the
//           box depth, its orifice the circle ∩ the 16 mm slab;
//   funnel  a cone frustum on the vertical axis through (width/2, depth/2): orifice at
//           pour_height_m above the floor, top `funnel.height_m` higher;
//   feed    a region `feed_width_m` wide (x) over the full depth, just above the funnel top (with
//           funnel.enabled = false: its bottom at pour_height_m, the grains fall straight down).
//
// Funnel discharge time: from the first grain below the orifice to the first moment after the
// feed has ended with no grain left at or above the orifice height (resolution: the sampling
// interval). Without a funnel the same clock times the stream leaving the feed region.
//
// Usage:
//   core::Scene model = ...;  ApplyFidelity(fidelity, &model);
//   SegregationRun run = RunSegregation(model, settings, seed, {});
//   if (run.ok()) use(run.analysis->indices.whole.species[2].mass.s_n);
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/scene/scene.h"
#include "experiments/aor/aor_experiment.h"
#include "experiments/segregation/funnel_geometry.h"
#include "objectives/common/feed.h"
#include "objectives/metrics/discharge_metrics.h"
#include "objectives/metrics/granule_tracking.h"
#include "objectives/metrics/heap_segregation.h"
#include "objectives/metrics/repose_angle.h"
#include "objectives/metrics/segregation_floor.h"
#include "objectives/common/settled_run.h"
#include "objectives/common/snapshot.h"

namespace demcal::objectives {

// Which granules are followed (Figs. 17–19) and how often their state is recorded.
struct TrackingSettings {
  int granules = 20;  // 0: none
  int species = -1;   // −1: the feed component with the smallest mass fraction
  double sample_interval_s = 0.002;
  double start_fraction = 0.3;  // of the pour: later granules land on a heap, not the floor
  SurfaceOptions surface;
  ImpactOptions impact;
};

struct SegregationSettings {
  Feed feed;                   // the paper: BP/TAED/EP 0.925/0.055/0.02 at 20 g/s, 30.85 g
  double width_m = 0.2;        // box width (x): holds the ~150 mm base of the paper's heap
  double depth_m = 0.016;      // box depth (y), the paper's 16 mm
  double pour_height_m = 0.1;  // funnel orifice (or feeder bottom) above the floor
  double feed_width_m = 0.04;  // feed region x extent
  FunnelSettings funnel;
  int wall_material = 0;  // box faces, floor and funnel (Perspex in the paper)
  // The funnel's own material, -1: wall_material. A separate one lets the slab's wall friction
  // change without changing the flow through the funnel.
  int funnel_material = -1;
  int FunnelMaterial() const { return funnel_material >= 0 ? funnel_material : wall_material; }
  bool glued_base = true;
  SettleCriteria settle;           // feed_end_s is set from the feed
  ReposeAngleOptions angle;        // base_z_m is set from the base
  HeapBinOptions bins;             // y range is set from the box
  SegregationOptions segregation;  // random.seed is derived from the run's seed
  SegregationFloorOptions floor;   // random-mixture noise floor; seed derived from the run's seed
  TrackingSettings tracking;
  double max_wall_time_s = 0;  // per run; 0 = unlimited
  bool IsValid(const core::Scene& model, std::string* error) const;
  // The tracked species (tracking.species, or the minor feed component).
  int TrackedSpecies() const;
};

// A followed granule: its samples below the funnel, the first impact and the final depth.
struct TrackedGranule {
  GranuleTrack track;
  std::optional<int> impact_sample;  // FirstSpeedDropIndex
  double impact_time_s = 0;
  double peak_specific_kinetic_J_kg = 0;   // ½v² at the highest speed before the impact
  std::optional<Penetration> penetration;  // below the settled heap's surface
};

struct SegregationRun {
  uint64_t seed = 0;
  SettleResult settle;
  bool funnel_emptied = false;
  double discharge_time_s = 0;  // see the file comment; 0 when the funnel did not empty
  double first_out_s = 0, empty_s = 0;
  double feed_duration_s = 0;        // the pour's length (FeedTookS: mass / rate, or longer when
                                     // the feed's factory could not insert that fast)
  bool funnel_feed_limited = false;  // FeedLimited (funnel_clock.h): the time measures the feed
  // FunnelRegime (funnel_clock.h): "orifice_limited", "feed_limited", "not_emptied" or "no_funnel".
  std::string funnel_regime = "no_funnel";
  // Steady outflow (kg/s): the slope of the mass out between 20 % and 80 % of it (discharge
  // metrics); an orifice-limited funnel passes less than the feed rate, a feed-limited one the
  // feed rate. 0 without a funnel or outflow.
  double funnel_mass_flow_kg_s = 0;
  // The orifice this run had (FunnelSettings::OrificeDiameterM at its fidelity); 0 without a
  // funnel.
  double funnel_orifice_diameter_m = 0;
  int64_t spheres_left_above = 0;  // at or above the orifice at the end
  // What left the funnel (grains first seen below the orifice plane), in time bins from the
  // first grain out to the discharge end: the paper's Fig. 16 (pre-segregation in the funnel
  // shows as a drift of a species' fraction). Empty without a funnel or when nothing left.
  std::vector<CompositionBin> outflow;
  std::vector<double> outflow_mass_fraction;  // per species, of all that left the funnel
  Snapshot heap;                   // the settled heap below the funnel (glued base excluded)
  std::optional<HeapSegregationAnalysis> analysis;
  std::string analysis_message;  // why analysis is empty
  std::optional<HeapFloor> floor;  // the indices' random-mixture noise floor (with analysis)
  ReposeAngle angle;
  ReposeAngleOptions angle_options;  // as measured (base height set)
  std::vector<TrackedGranule> tracked;
  int64_t particles = 0;  // grains in the heap
  double wall_time_s = 0;
  // "ok", the settle status, "funnel_not_empty" or "no_analysis".
  std::string Status() const;
  bool ok() const { return Status() == "ok"; }
};

// The scene of one run; *fixed_count = glued spheres, which hold the first particle ids.
core::Scene BuildSegregationScene(const core::Scene& model, const SegregationSettings& settings,
                                  uint64_t seed, int64_t* fixed_count);

SegregationRun RunSegregation(const core::Scene& model, const SegregationSettings& settings,
                              uint64_t seed, const RunHooks& hooks);

}  // namespace demcal::objectives
