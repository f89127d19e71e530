#include "files/input_file.h"

#include "core/io/input_file.h"

namespace demcal::workflow {

bool ReadInputFile(const std::string& path, const std::string& what, size_t max_bytes,
                   std::string* text, std::string* error) {
  return core::io::ReadRegularFile(path, what, max_bytes, {}, text, error);
}

}  // namespace demcal::workflow
