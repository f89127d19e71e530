// libFuzzer harness: the STL reader (ASCII and binary) on arbitrary bytes. A read either
// succeeds with finite, bounded triangles or fails with a message naming the source.
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "core/walls/mesh_io.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  const demcal::core::StlReadResult r = demcal::core::ParseStl(bytes, "fuzz.stl");
  if (r.ok()) {
    for (const demcal::core::StlTriangle& t : r.triangles)
      for (const demcal::core::Vec3& v : t.v)
        if (!(std::abs(v.x) <= 1e6 && std::abs(v.y) <= 1e6 && std::abs(v.z) <= 1e6)) std::abort();
  } else if (r.message.rfind("fuzz.stl", 0) != 0) {
    std::abort();  // every failure names the file
  }
  return 0;
}
