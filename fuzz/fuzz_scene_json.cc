// libFuzzer harness: the scene reader (JSON text → validated core::Scene). Never crashes or
// hangs; a failure names the source.
#include <cstdint>
#include <cstdlib>
#include <string>

#include "files/scene_json.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  demcal::workflow::SceneFile file;
  std::string error;
  // Mesh walls name files relative to the source; "/nonexistent/" keeps the fuzzer off disk.
  if (!demcal::workflow::ParseSceneText(text, "/nonexistent/fuzz.json", &file, &error) &&
      error.rfind("/nonexistent/fuzz.json", 0) != 0)
    std::abort();
  return 0;
}
