// libFuzzer harness: the workflow reader (workflow::LoadWorkflowFile, `demcal reproduce FILE`).
// A workflow names experiment files and tables relative to its folder, and none exist there.
// Never crashes; a refusal names the workflow file or the file it refers to.
#include <cstdint>
#include <cstdlib>
#include <string>

#include "fuzz/fuzz_input_file.h"
#include "workflow/reproduce/workflow_file.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string path = demcal::fuzz::WriteFuzzInput("workflow.json", data, size);
  if (path.empty()) return 0;
  demcal::workflow::WorkflowFile workflow;
  std::string error;
  // A refusal names a file: the workflow, or a file it names (absolute paths).
  if (!demcal::workflow::LoadWorkflowFile(path, &workflow, &error) &&
      (error.empty() || error[0] != '/'))
    std::abort();
  return 0;
}
