// libFuzzer harness: the measurement table reader (CSV). The bytes go to a file because
// LoadMeasurementTable reads a path. Never crashes; a failure names the file.
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "workflow/files/measurement_table.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const std::string path = "/tmp/demcal_fuzz_table_" + std::to_string(::getpid()) + ".csv";
  FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) return 0;
  std::fwrite(data, 1, size, f);
  std::fclose(f);
  demcal::workflow::MeasurementTable table;
  std::string error;
  if (!demcal::workflow::LoadMeasurementTable(path, &table, &error) &&
      error.rfind(path, 0) != 0)
    std::abort();
  return 0;
}
