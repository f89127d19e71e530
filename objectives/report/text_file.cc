#include "objectives/report/text_file.h"

#include "core/io/atomic_file.h"

namespace demcal::objectives {

bool WriteTextFile(const std::string& path, const std::function<void(std::ostream&)>& write,
                   std::string* error) {
  return core::io::WriteFileAtomically(path, write, error);
}

}  // namespace demcal::objectives
