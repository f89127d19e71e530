#pragma once
// Angle-of-repose experiment (paper section 2.5.2; docs/physics.md §5.1): a feed of one species
// or a mixture is poured at a mass rate from a set height onto a rough base (a glued particle
// layer), either into a pseudo-2D box (slot heap with two flanks, the paper's test box) or onto a disc
// (free conical heap, the excess runs off the edge); when the heap has settled its angle is
// measured from the surface profile (repose_angle.h).
//
// Geometry (z up, floor at z = 0): slot box x ∈ [0, width], y ∈ [0, depth], feed centred at
// x = width/2; conical: base disc of diameter `width` centred on the z axis, inside a confining
// cylinder of 1.6× its radius that catches the run-off.
//
// Usage:
//   core::Scene model = ...;            // materials, species, interactions, contact model
//   ApplyFidelity(fidelity, &model);
//   AorRun run = RunAor(model, settings, seed, {});
//   if (run.ok()) use(run.angle.angle_deg);
#include <cstdint>
#include <string>

#include "core/scene/scene.h"
#include "objectives/common/feed.h"
#include "objectives/metrics/repose_angle.h"
#include "objectives/common/run_hooks.h"
#include "objectives/common/settled_run.h"
#include "objectives/common/snapshot.h"

namespace demcal::objectives {

struct AorSettings {
  enum class Heap { kSlot, kConical };
  Heap heap = Heap::kSlot;
  Feed feed;
  double width_m = 0.1;        // slot: box width (x); conical: base disc diameter
  double depth_m = 0.016;      // slot: box depth (y), the paper's 16 mm
  double pour_height_m = 0.08; // bottom of the feed region above the floor
  double feed_width_m = 0.012; // feed region: x extent (slot) or diameter (conical)
  int wall_material = 0;       // box faces, floor and confining cylinder
  bool glued_base = true;      // false: a plain floor (the heap may slide)
  SettleCriteria settle;       // feed_end_s is set from the feed
  ReposeAngleOptions angle;    // base_z_m is set from the base
  double max_wall_time_s = 0;  // per run; 0 = unlimited
  bool IsValid(const core::Scene& model, std::string* error) const;
};

struct AorRun {
  uint64_t seed = 0;
  SettleResult settle;
  ReposeAngle angle;
  ReposeAngleOptions angle_options;  // as measured (base height set)
  Snapshot heap;            // the settled heap (glued base and conical run-off excluded)
  int64_t particles = 0;    // poured particles
  double wall_time_s = 0;
  bool ok() const { return settle.ok() && angle.ok; }
  // "ok", the settle status, or "no_angle".
  std::string Status() const { return !settle.ok() ? settle.status : angle.ok ? "ok" : "no_angle"; }
};

// The scene of one run (model + geometry + feed + glued base); *fixed_count = glued spheres,
// which hold the first particle ids.
core::Scene BuildAorScene(const core::Scene& model, const AorSettings& settings, uint64_t seed,
                          int64_t* fixed_count);

AorRun RunAor(const core::Scene& model, const AorSettings& settings, uint64_t seed,
              const RunHooks& hooks);

}  // namespace demcal::objectives
