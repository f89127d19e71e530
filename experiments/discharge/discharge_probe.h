#pragma once
// The funnel discharge experiment (discharge_experiment.h) as a calibration probe: one fill and
// discharge per replicate, reporting discharge_time_s, mass_flow_kg_s and bulk_density_kg_m3
// (the latter only when the hopper has a density probe, i.e. a value > 0).
//
//   DischargeProbe funnel(settings);
//   ProbeOutcome o = funnel.Run(model_at_fidelity, seed);
#include "calibrate/experiment_probe.h"
#include "experiments/discharge/discharge_experiment.h"

namespace demcal::calibrate {

class DischargeProbe final : public ExperimentProbe {
 public:
  explicit DischargeProbe(objectives::DischargeSettings settings) : settings_(std::move(settings)) {}
  std::string Kind() const override { return "discharge"; }
  std::vector<std::string> Observables() const override;
  ProbeOutcome Run(const core::Scene& model, uint64_t seed) const override;

 private:
  objectives::DischargeSettings settings_;
};

}  // namespace demcal::calibrate
