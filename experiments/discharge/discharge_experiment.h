#pragma once
// Funnel discharge experiment (Alizadeh et al. 2018 section 3.3, Fig. 16): a conical
// hopper is filled with a feed while a gate closes its orifice; the gate opens at t0 (once the
// fill has settled, or at a set time) and the mass that leaves through the orifice is recorded
// per species over time until the hopper is empty, the flow stalls (a jam) or a time limit. The
// discharge time, mass flow rate and outflow composition follow from discharge_metrics.h.
//
// Geometry (z up, axis = z axis, orifice plane z = 0): a cone frustum from the orifice (diameter
// orifice_diameter_m at z = 0) up to the top diameter at z = cone height, an optional cylinder
// above it; the gate is a horizontal plane at z = 0 that moves down fast enough at t0 that the
// falling grains never catch it again, and stops below the catch floor. Grains that left fall
// onto the floor of a catch bin catch_depth_m below the orifice (the engine ends a run when a
// grain leaves its domain, so the outflow stays inside it).
//
// Outflow: every sample_interval_s after t0, the cumulative mass per species of the grains whose
// centre has crossed below the orifice plane (a grain counts once, when first seen below). The
// run stops once analysis.discharge_fraction of the fill is out: nothing later enters the
// metrics, and a slow tail (grains trickling off the cone) costs no time.
//
// Usage:
//   core::Scene model = ...;             // materials, species, interactions, contact model
//   ApplyFidelity(fidelity, &model);
//   DischargeRun run = RunDischarge(model, settings, seed, {});
//   if (run.ok()) use(run.metrics.mass_flow_kg_s, run.metrics.discharge_time_s);
#include <cstdint>
#include <string>
#include <vector>

#include "core/scene/scene.h"
#include "objectives/metrics/discharge_metrics.h"
#include "objectives/common/feed.h"
#include "objectives/common/run_hooks.h"
#include "objectives/common/settled_run.h"

namespace demcal::objectives {

struct HopperGeometry {
  double top_diameter_m = 0.06;
  double orifice_diameter_m = 0.01;
  double cone_half_angle_deg = 30;  // from the axis; (0, 89]
  double cylinder_height_m = 0.04;  // straight section above the cone; 0: none
  double ConeHeightM() const;       // orifice plane to cone top
  double TopM() const;              // orifice plane to the hopper's rim
};

struct DischargeSettings {
  enum class Fill { kPour, kPlace };
  // kPour: the feed factory pours `feed` at its rate from above the hopper. kPlace: the feed's
  // mass (counts from the mean grain masses) is placed at t = 0 on a loose jittered lattice
  // inside the hopper (hopper_fill.h) and settles; the feed's rate is ignored.
  Fill fill = Fill::kPour;
  Feed feed;
  HopperGeometry hopper;
  double feed_diameter_m = 0;    // pour region diameter; 0: 0.6 × top diameter
  double catch_depth_m = 0.06;   // catch floor below the orifice plane
  int wall_material = 0;         // hopper, gate and catch bin
  // The gate opens when the fill has settled (settle criterion; feed_end_s set from the feed)
  // or, when gate_open_s > 0, at that time.
  SettleCriteria settle;
  double gate_open_s = 0;
  double sample_interval_s = 0.01;
  double stall_s = 1;            // no outflow for this long with grains left: "jammed"
  double max_discharge_s = 20;   // after t0: status "not_empty"
  DischargeOptions analysis;     // expected_total_mass_kg is set from the fill at t0
  double max_wall_time_s = 0;    // per run; 0 = unlimited

  bool IsValid(const core::Scene& model, std::string* error) const;
};

struct DischargeRun {
  uint64_t seed = 0;
  // "ok"; "jammed", "not_empty" (max_discharge_s reached), "not_settled", "invalid_scene" or a
  // core termination name.
  std::string status = "not_run";
  std::string message;
  double gate_open_s = 0;
  double fill_mass_kg = 0;        // above the orifice plane at t0
  double bulk_density_kg_m3 = 0;  // of the fill at t0, in a probe inside the hopper (0: no probe)
  std::vector<OutflowSample> samples;
  DischargeMetrics metrics;
  int64_t particles = 0;
  double wall_time_s = 0;
  bool ok() const { return status == "ok" && metrics.ok; }
};

// The scene of one run with the gate closed at t = 0 and opening at gate_open_s (a very late time
// when the opening waits for the settle criterion).
core::Scene BuildDischargeScene(const core::Scene& model, const DischargeSettings& settings,
                                uint64_t seed);
// Moves the gate's opening in `scene` (built by BuildDischargeScene) to t0_s.
void OpenGateAt(double t0_s, core::Scene* scene);

DischargeRun RunDischarge(const core::Scene& model, const DischargeSettings& settings,
                          uint64_t seed, const RunHooks& hooks);

}  // namespace demcal::objectives
