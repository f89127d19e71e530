#include "objectives/report/text_file.h"

#include <fstream>

namespace demcal::objectives {

bool WriteTextFile(const std::string& path, const std::function<void(std::ostream&)>& write,
                   std::string* error) {
  std::ofstream out(path, std::ios::trunc);
  if (out) write(out);
  out.flush();
  if (out) return true;
  if (error) *error = "cannot write '" + path + "'";
  return false;
}

}  // namespace demcal::objectives
