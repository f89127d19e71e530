#pragma once
// DetectionLimitsAtFit: what the data could not have seen, per candidate effect still open at the
// end of a diagnosis (detection_limit.h; docs/diagnose/ranking.md, "What the data could not
// see"). Taken at the fit the answer ends on (the base with its re-valued parameters and named
// effects, their signatures as fitted directions), with each candidate's signature of the last
// candidate step (per unit of its parameter, secant-corrected by its refits), the floor that fit
// leaves and that step's level α/K. Controls, named, re-valued and tied effects and other laws
// of a named mechanism are left out: the answer already speaks of them.
//
// Thread-safety: pure function.
#include <vector>

#include "diagnose/loop/diagnosis.h"
#include "diagnose/loop/fit_state.h"

namespace demcal::diagnose {

// unit_signatures: per entry of `step`, its raw signature per unit of its parameter.
std::vector<EffectDetection> DetectionLimitsAtFit(
    const std::vector<Observation>& observations, const FitState& fit, const DiagnosisStep& step,
    const std::vector<std::vector<double>>& unit_signatures,
    const std::vector<CandidateEffect>& candidates, const DiagnoseOptions& options,
    const Diagnosis& d);

}  // namespace demcal::diagnose
