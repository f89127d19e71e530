// libFuzzer harness: the study reader (workflow::LoadStudyFile). A study names experiment files
// relative to its folder, and none exist there. Never crashes; a refusal names the study file or
// the file it refers to.
#include <cstdint>
#include <cstdlib>
#include <string>

#include "fuzz/fuzz_input_file.h"
#include "workflow/calibration/study_file.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string path = demcal::fuzz::WriteFuzzInput("study.json", data, size);
  if (path.empty()) return 0;
  demcal::workflow::StudyFile study;
  std::string error;
  // A refusal names a file: the study, or an experiment file it names (absolute paths).
  if (!demcal::workflow::LoadStudyFile(path, &study, &error) && (error.empty() || error[0] != '/'))
    std::abort();
  return 0;
}
