// libFuzzer harness: the evaluation journal reader (calibrate::EvaluationJournal::Open on a
// JSON-lines file). The bytes go to a file because the journal opens a path. Never crashes; a
// refusal names the file (and the line).
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "calibrate/evaluation_journal.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const std::string path =
      "/tmp/demcal_fuzz_journal_" + std::to_string(::getpid()) + ".jsonl";
  FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) return 0;
  std::fwrite(data, 1, size, f);
  std::fclose(f);
  std::string error;
  {
    demcal::calibrate::EvaluationJournal journal;
    if (!journal.Open(path, "fuzz-study", &error, 2) && error.rfind(path, 0) != 0 &&
        error.find(path) == std::string::npos)
      std::abort();
  }
  std::remove(path.c_str());
  return 0;
}
