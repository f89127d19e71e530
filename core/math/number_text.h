#pragma once
// NumberText: a double as a message prints it — 6 significant digits by default, the
// shortest form ("0.25", "1e+308", "3.5e-05"), never std::to_string's fixed six decimals
// ("0.000035", "100.000000") that hide small values and pad large ones. Summaries that
// round further (χ² figures, floors: 3 digits) pass their own digit count.
#include <sstream>
#include <string>

namespace demcal::core {

inline std::string NumberText(double value, int significant_digits = 6) {
  std::ostringstream os;
  os.precision(significant_digits);
  os << value;
  return os.str();
}

}  // namespace demcal::core
