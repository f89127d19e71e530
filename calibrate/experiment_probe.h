#pragma once
// ExperimentProbe: one replicate of a virtual experiment seen as a black box by the calibration:
// a particle model and a seed in, every observable the experiment measures out (by registered
// name, observable_registry.h), or a failure status. One run feeds every target that reads the
// same experiment under the same condition (the angle and the heap height of one heap), so a
// study pays for each heap once.
//
// Failures are values of the status, never exceptions (Ceres' CostFunction contract: a sample
// that cannot be computed is reported, and the optimiser treats it as infeasible).
//
// An experiment becomes a calibration target with a probe in its room
// (experiments/<name>/<name>_probe.h) named in its registry entry (<name>_kind.cc).
//
// Thread-safety: Run is called concurrently for different replicates and candidates and must be
// reentrant.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "core/scene/scene.h"

namespace demcal::calibrate {

struct ProbeOutcome {
  std::string status = "ok";             // "ok", or why there are no values
  std::map<std::string, double> values;  // observable name -> value (SI / the name's unit)
  double wall_time_s = 0;
  bool ok() const { return status == "ok"; }
};

class ExperimentProbe {
 public:
  virtual ~ExperimentProbe() = default;
  virtual std::string Kind() const = 0;                      // "aor", "discharge", ...
  virtual std::vector<std::string> Observables() const = 0;  // what Run reports when ok
  virtual ProbeOutcome Run(const core::Scene& model, uint64_t seed) const = 0;
};

}  // namespace demcal::calibrate
