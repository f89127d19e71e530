// libFuzzer harness: the evaluation journal reader (calibrate::EvaluationJournal::Open on a
// JSON-lines file, which opens a path). Never crashes; a refusal names the file (and the line).
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "calibrate/evaluation_journal.h"
#include "fuzz/fuzz_input_file.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string path = demcal::fuzz::WriteFuzzInput("journal.jsonl", data, size);
  if (path.empty()) return 0;
  std::string error;
  {
    demcal::calibrate::EvaluationJournal journal;
    if (!journal.Open(path, "fuzz-study", &error, 2) && error.find(path) == std::string::npos)
      std::abort();
  }
  std::remove(path.c_str());  // Open may append to an existing journal
  return 0;
}
