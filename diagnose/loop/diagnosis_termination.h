#pragma once
// DiagnosisTermination: how a discrepancy diagnosis ended. Code decides on the enum;
// diagnosis.json and the reports carry its name, and DiagnosisTerminationName is the one place
// the two meet. The names are part of diagnosis.json's format: never rename one.
//
//   if (d.termination == DiagnosisTermination::kEffectFound) ...;
//   json["termination"] = DiagnosisTerminationName(d.termination);
namespace demcal::diagnose {

enum class DiagnosisTermination {
  kNoMissingEffect,  // "no_missing_effect": the base model fits within noise
  kEffectFound,      // "effect_found": added effects close the gap
  kGapRemains,       // "gap_remains": effects were added, a gap remains unexplained
  kGapUnexplained,   // "gap_unexplained": a gap, and no effect of the library explains it
  kFailed,           // "failed": the base calibration gave no prediction
  kInvalid,          // "invalid": the options were refused before any run
};

const char* DiagnosisTerminationName(DiagnosisTermination t);

}  // namespace demcal::diagnose
