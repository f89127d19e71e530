#pragma once
// The angle-of-repose experiment (aor_experiment.h) as a calibration probe: one poured, settled
// and measured heap per replicate, reporting angle_deg (mean of the flank fits), heap_height_m
// and crest_drop_m (objectives/metrics/heap_crest.h).
//
//   AorProbe heap(settings);   // settings parsed from the experiment's "aor" section
//   ProbeOutcome o = heap.Run(model_at_fidelity, seed);
#include "calibrate/experiment_probe.h"
#include "experiments/aor/aor_experiment.h"

namespace demcal::calibrate {

class AorProbe final : public ExperimentProbe {
 public:
  explicit AorProbe(objectives::AorSettings settings) : settings_(std::move(settings)) {}
  std::string Kind() const override { return "aor"; }
  std::vector<std::string> Observables() const override;
  ProbeOutcome Run(const core::Scene& model, uint64_t seed) const override;

 private:
  objectives::AorSettings settings_;
};

}  // namespace demcal::calibrate
