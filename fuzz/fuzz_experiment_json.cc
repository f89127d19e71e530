// libFuzzer harness: the experiment reader (demcal-experiment/1: particle model, fidelity and
// the aor / discharge / segregation sections). Never crashes; a failure names the source.
#include <cstdint>
#include <cstdlib>
#include <string>

#include "workflow/files/aor_json.h"
#include "workflow/files/discharge_json.h"
#include "workflow/files/experiment_file.h"
#include "workflow/files/json_document.h"
#include "workflow/files/segregation_json.h"

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
  demcal::objectives::AorSettings aor;
  demcal::objectives::DischargeSettings discharge;
  demcal::objectives::SegregationSettings segregation;
  if (file.experiment == "aor") ParseAorSection(file.section, "fuzz.json", file.model, &aor, &error);
  if (file.experiment == "discharge")
    ParseDischargeSection(file.section, "fuzz.json", file.model, &discharge, &error);
  if (file.experiment == "segregation")
    ParseSegregationSection(file.section, "fuzz.json", file.model, &segregation, &error);
  return 0;
}
