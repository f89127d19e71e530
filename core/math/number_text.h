#pragma once
// NumberText: a double as a message prints it — 6 significant digits, the shortest form
// ("0.25", "1e+308", "3.5e-05"), never std::to_string's fixed six decimals ("0.000035",
// "100.000000") that hide small values and pad large ones.
#include <sstream>
#include <string>

namespace demcal::core {

inline std::string NumberText(double value) {
  std::ostringstream os;
  os << value;
  return os.str();
}

}  // namespace demcal::core
