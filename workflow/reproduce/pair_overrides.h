#pragma once
// The workflow's segregation.pair_overrides on the heap's experiment file (stage 6), after stage
// 1's values: pair properties that no stage calibrates, such as the EP–BP rolling friction that
// Table 1 gives only per material. Each is said in the file's description, which every
// scenario's result.json carries. A material the file does not have, or the property that stage
// 1 calibrates (or holds) on a species' own pair, is refused with the field's path; the file is
// then left unchanged.
//
//   if (!ApplyPairOverrides(workflow, &experiment, &error)) ...;
#include <nlohmann/json.hpp>
#include <string>

#include "workflow/reproduce/workflow_file.h"

namespace demcal::workflow {

bool ApplyPairOverrides(const WorkflowFile& w, nlohmann::ordered_json* experiment,
                        std::string* error);

}  // namespace demcal::workflow
