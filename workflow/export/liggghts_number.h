#pragma once
// Num: a double in the shortest form that reads back to the same value, for deck text.
#include <charconv>
#include <string>

namespace demcal::workflow {

inline std::string Num(double v) {
  char buffer[32];
  const auto r = std::to_chars(buffer, buffer + sizeof buffer, v);
  return std::string(buffer, r.ptr);
}

}  // namespace demcal::workflow
