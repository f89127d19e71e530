#pragma once
// The whole workflow checked before stage 1 (a workflow file that parses can still fail a late
// stage): species, coating levels and reference keys each listed once; the synthetic table
// holding synthetic rows only; the coated material and its partners materials of the experiment
// files that use them; and the calibrations of stages 1 and 3 parsed as they will run. The
// message names the workflow file and its field.
//
//   if (!CheckWorkflowWhole(workflow, &error)) { log << "error: " << error; return 2; }
#include <string>

#include "workflow/reproduce/workflow_file.h"

namespace demcal::workflow {

bool CheckWorkflowWhole(const WorkflowFile& workflow, std::string* error);

}  // namespace demcal::workflow
