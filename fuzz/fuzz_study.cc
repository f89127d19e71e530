// libFuzzer harness: the study reader (workflow::LoadStudyFile). The bytes go to a file in a
// directory of their own (a study names experiment files relative to it, and none exist there).
// Never crashes; a refusal names the study file or the file it refers to.
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "workflow/files/study_file.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const std::string dir = [] {
    const std::string d = "/tmp/demcal_fuzz_study_" + std::to_string(::getpid());
    std::filesystem::create_directories(d);
    return d;
  }();
  static const std::string path = dir + "/study.json";
  FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) return 0;
  std::fwrite(data, 1, size, f);
  std::fclose(f);
  demcal::workflow::StudyFile study;
  std::string error;
  // A refusal names a file: the study, or an experiment file it names (absolute paths).
  if (!demcal::workflow::LoadStudyFile(path, &study, &error) && (error.empty() || error[0] != '/'))
    std::abort();
  return 0;
}
