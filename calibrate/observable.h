#pragma once
// Observable: a simulated measurement the calibration compares with a measured one — one
// replicate of a virtual experiment (objectives/) for a particle model and a seed, giving one
// number or a failure status. The calibration treats it as a black box; failures are values of
// the status, never exceptions (Ceres' CostFunction contract: a sample that cannot be computed
// is reported, and the optimiser treats it as infeasible).
//
// Adding an observable is one file implementing this interface plus one line in
// observable_registry.cc.
//
// Thread-safety: Run is called concurrently for different replicates and must be reentrant.
#include <cstdint>
#include <memory>
#include <string>

#include "core/scene.h"

namespace demcal::calibrate {

struct ReplicateOutcome {
  std::string status = "ok";  // "ok", or why there is no value (settle status, "no_angle", ...)
  double value = 0;
  double wall_time_s = 0;
};

class Observable {
 public:
  virtual ~Observable() = default;
  virtual std::string Name() const = 0;  // e.g. "angle_deg"
  virtual std::string Unit() const = 0;  // e.g. "deg"
  virtual ReplicateOutcome Run(const core::Scene& model, uint64_t seed) const = 0;
};

}  // namespace demcal::calibrate
