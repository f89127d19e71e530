// libFuzzer harness: the JSON reading discipline every input file goes through (depth limit,
// number range, duplicate keys, syntax errors with line and column). Never crashes; a failure
// names the source; an accepted document is no deeper than the limit.
#include <cstdint>
#include <cstdlib>
#include <string>

#include "files/json_document.h"

namespace {
int Depth(const nlohmann::json& j) {
  int deepest = 0;
  if (j.is_structured())
    for (const auto& child : j) deepest = std::max(deepest, Depth(child));
  return (j.is_structured() ? 1 : 0) + deepest;
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  nlohmann::json document;
  std::string error;
  if (demcal::workflow::ParseJsonText(text, "fuzz.json", &document, &error)) {
    if (Depth(document) > demcal::workflow::kMaxJsonDepth) std::abort();
    (void)document.dump();
  } else if (error.rfind("fuzz.json: ", 0) != 0) {
    std::abort();
  }
  return 0;
}
