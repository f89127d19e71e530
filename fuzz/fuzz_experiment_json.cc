// libFuzzer harness: the experiment reader (demcal-experiment/1: particle model, fidelity and
// every registered experiment's section). Never crashes; a failure names the source.
#include <cstdint>
#include <cstdlib>
#include <string>

#include "experiments/common/experiment_file.h"
#include "experiments/experiment_registry.h"
#include "files/json_document.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace demcal::workflow;
  const std::string text(reinterpret_cast<const char*>(data), size);
  nlohmann::json document;
  std::string error;
  ExperimentFile file;
  if (!ParseJsonText(text, "fuzz.json", &document, &error) ||
      !ParseExperimentJson(document, "fuzz.json", &file, &error)) {
    if (error.rfind("fuzz.json", 0) != 0) std::abort();
    return 0;
  }
  FindExperimentKind(file.experiment)->check_section(file, &error);
  return 0;
}
