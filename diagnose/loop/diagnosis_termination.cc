#include "diagnose/loop/diagnosis_termination.h"

namespace demcal::diagnose {

const char* DiagnosisTerminationName(DiagnosisTermination t) {
  switch (t) {
    case DiagnosisTermination::kNoMissingEffect:
      return "no_missing_effect";
    case DiagnosisTermination::kEffectFound:
      return "effect_found";
    case DiagnosisTermination::kGapRemains:
      return "gap_remains";
    case DiagnosisTermination::kGapUnexplained:
      return "gap_unexplained";
    case DiagnosisTermination::kFailed:
      return "failed";
    case DiagnosisTermination::kInvalid:
      return "invalid";
    case DiagnosisTermination::kBaseUnsettled:
      return "base_unsettled";
    case DiagnosisTermination::kNotToldApart:
      return "not_told_apart";
    case DiagnosisTermination::kModelFormOffset:
      return "model_form_offset";
  }
  return "unknown";
}

}  // namespace demcal::diagnose
