#pragma once
// MakeEffectContext: what the candidate effects act on in a study (effect.h) — the subject
// species (the one made of the material of the study's first parameter: named like that
// material if several are, else the first; or the one the user names), the wall materials
// (those no species of the first experiment is made of) and the coating covariate (a numeric
// condition column of the targets whose name starts with "coating", with its largest value).
//
//   EffectContext c;
//   if (!MakeEffectContext(study, "", &c, &error)) ...;
//
// Thread-safety: pure function.
#include <string>

#include "diagnose/effects/effect.h"
#include "workflow/calibration/study_file.h"

namespace demcal::diagnose {

bool MakeEffectContext(const workflow::StudyFile& study, const std::string& species, EffectContext* out,
                       std::string* error);

}  // namespace demcal::diagnose
