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
  kGapUnexplained,   // "gap_unexplained": no longer written (model_form_offset says it); kept for
                     // old files
  kFailed,           // "failed": the base calibration gave no prediction
  kInvalid,          // "invalid": the options were refused before any run
  kBaseUnsettled,    // "base_unsettled": the base calibration did not settle (base_fit.h): nothing
                     // ranked
  kNotToldApart,     // "not_told_apart": two effects explain the gap about equally (ranking.h)
  kModelFormOffset,  // "model_form_offset": a gap no effect explains beyond the discrepancy floor
};

const char* DiagnosisTerminationName(DiagnosisTermination t);

}  // namespace demcal::diagnose
