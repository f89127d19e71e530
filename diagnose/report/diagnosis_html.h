#pragma once
// report.html of a diagnosis: the verdict, the gap before and after per observable and
// condition, the ranking and the signatures, where the gap was and what the diagnosis cost —
// the same content as diagnosis.json and the SVG plots, as one self-contained page
// (outputs/html_report.h). Synthetic inputs carry the report's "synthetic" badge.
#include <string>

#include "diagnose/report/diagnosis_outputs.h"

namespace demcal::diagnose {

bool WriteDiagnosisHtml(const std::string& path, const DiagnosisRunInfo& info, const Diagnosis& d,
                        std::string* error);

}  // namespace demcal::diagnose
