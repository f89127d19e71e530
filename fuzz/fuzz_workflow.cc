// libFuzzer harness: the workflow reader (workflow::LoadWorkflowFile, `demcal reproduce FILE`).
// The bytes go to a file in a directory of their own (a workflow names experiment files and
// tables relative to it, and none exist there). Never crashes; a refusal names the workflow file
// or the file it refers to.
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "workflow/reproduce/workflow_file.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const std::string dir = [] {
    const std::string d = "/tmp/demcal_fuzz_workflow_" + std::to_string(::getpid());
    std::filesystem::create_directories(d);
    return d;
  }();
  static const std::string path = dir + "/workflow.json";
  FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) return 0;
  std::fwrite(data, 1, size, f);
  std::fclose(f);
  demcal::workflow::WorkflowFile workflow;
  std::string error;
  // A refusal names a file: the workflow, or a file it names (absolute paths).
  if (!demcal::workflow::LoadWorkflowFile(path, &workflow, &error) &&
      (error.empty() || error[0] != '/'))
    std::abort();
  return 0;
}
