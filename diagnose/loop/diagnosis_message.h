#pragma once
// The diagnosis' answer in words (Diagnosis::message): the verdict, the named effects with their
// sign and value, ties and the measurement that would separate them, the screen's directed test,
// a base on a bound or unsettled, and the model-form readings, from the filled Diagnosis (its
// final_point, gaps and notes). Kept apart from the loop (diagnosis.cc), which decides; this
// only says.
#include <string>
#include <vector>

#include "diagnose/loop/diagnosis.h"

namespace demcal::diagnose {

std::string DiagnosisMessage(const Diagnosis& d, const DiagnoseOptions& options,
                             const std::vector<CandidateEffect>& candidates);

}  // namespace demcal::diagnose
