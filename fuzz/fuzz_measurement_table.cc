// libFuzzer harness: the measurement table reader (CSV), which reads a path. Never crashes; a
// failure names the file.
#include <cstdint>
#include <cstdlib>
#include <string>

#include "fuzz/fuzz_input_file.h"
#include "files/measurement_table.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string path = demcal::fuzz::WriteFuzzInput("table.csv", data, size);
  if (path.empty()) return 0;
  demcal::workflow::MeasurementTable table;
  std::string error;
  if (!demcal::workflow::LoadMeasurementTable(path, &table, &error) && error.rfind(path, 0) != 0)
    std::abort();
  return 0;
}
