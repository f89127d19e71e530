#pragma once
// The calibrated parameter set of each segregation scenario, for use outside demcal reproduce:
//   DIR/params/<scenario>.json      "demcal-params/1": materials, species and interactions of
//                                   the scenario's experiment file (full-scale values: the
//                                   fidelity is applied on top when run), with provenance
//   DIR/params/<scenario>.liggghts  the same model as LIGGGHTS-PUBLIC `fix property/global`
//                                   lines (calibrate/liggghts_export.h; Γ in comments)
// Written from DIR/segregation/<scenario>/experiment.json (stage_segregation.cc); nothing when
// the segregation stage is disabled.
#include <string>

#include "workflow/reproduce/reproduce_context.h"

namespace demcal::workflow {

bool WriteScenarioParams(const ReproduceContext& ctx, std::string* error);

}  // namespace demcal::workflow
