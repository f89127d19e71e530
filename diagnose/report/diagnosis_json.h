#pragma once
// diagnosis.json (demcal-diagnosis/1) and diagnosed_params.json as JSON values
// (diagnosis_outputs.h lists the files; docs/diagnose.md every key).
#include <nlohmann/json.hpp>

#include "diagnose/report/diagnosis_outputs.h"

namespace demcal::diagnose {

nlohmann::ordered_json DiagnosisJson(const DiagnosisRunInfo& info, const Diagnosis& d);
nlohmann::ordered_json DiagnosedParamsJson(const DiagnosisRunInfo& info, const Diagnosis& d);

}  // namespace demcal::diagnose
