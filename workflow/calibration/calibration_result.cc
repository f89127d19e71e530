#include "workflow/calibration/calibration_result.h"

#include <cmath>

#include "outputs/exit_codes.h"

namespace demcal::workflow {

int ExitCodeOf(CalibrationStatus status) {
  switch (status) {
    case CalibrationStatus::kMatched: return kExitOk;
    case CalibrationStatus::kNotMatched: return kExitRunFailed;
    case CalibrationStatus::kInvalidInput: return kExitInvalidInput;
    case CalibrationStatus::kOutputUnavailable: return kExitInvalidInput;
    case CalibrationStatus::kOutputError: return kExitOutputError;
  }
  return kExitInternalError;
}

CalibrationResult CalibrationResultOf(const StudyFile& study,
                                      const calibrate::CalibrationSummary& s) {
  CalibrationResult r;
  r.termination = s.termination;
  r.message = s.message;
  for (size_t k = 0; k < study.space.Size(); ++k) {
    const calibrate::Parameter& p = study.space.parameters[k];
    CalibratedParameter out;
    out.name = p.name;
    out.property = calibrate::PairPropertyKey(p.property);
    out.material_a = study.parameter_materials[k].first;
    out.material_b = study.parameter_materials[k].second;
    if (s.best >= 0) out.value = s.candidates[s.best].parameters[k];
    if (k < s.estimates.size()) {
      if (std::isfinite(s.estimates[k].sigma)) out.sigma = s.estimates[k].sigma;
      out.identifiable = s.estimates[k].identifiable;
    }
    r.parameters.push_back(out);
  }
  for (size_t k = 0; k < s.residuals.size(); ++k) {
    const calibrate::TargetResidual& t = s.residuals[k];
    r.targets.push_back({t.name, t.observable, t.measured, t.uncertainty, t.simulated, t.sem,
                         t.residual, t.within_noise,
                         k < study.targets.size() ? study.targets[k].provenance : ""});
  }
  r.summary = s;
  return r;
}

}  // namespace demcal::workflow
