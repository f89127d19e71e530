#include "calibrate/condition.h"

#include <cmath>
#include <cstdlib>

namespace demcal::calibrate {

bool ParseConditionNumber(const std::string& text, double* out) {
  if (text.empty()) return false;
  // strtod also reads hexadecimal ("0x1p5" is 32): a table cell means what it shows in decimal,
  // so anything but digits, sign, point and exponent after leading blanks is not a number.
  const size_t start = text.find_first_not_of(" \t\n\v\f\r");
  if (start == std::string::npos ||
      text.find_first_not_of("0123456789+-.eE", start) != std::string::npos)
    return false;
  char* end = nullptr;
  *out = std::strtod(text.c_str(), &end);
  return end == text.c_str() + text.size() && std::isfinite(*out);
}

bool SameConditionCell(const std::string& a, const std::string& b) {
  double x = 0, y = 0;
  if (ParseConditionNumber(a, &x) && ParseConditionNumber(b, &y))
    return std::abs(x - y) <= 1e-12 * (1 + std::abs(x));
  return a == b;
}

bool ConditionIncludes(const Condition& condition, const Condition& part) {
  for (const auto& [column, cell] : part) {
    auto it = condition.find(column);
    if (it == condition.end() || !SameConditionCell(it->second, cell)) return false;
  }
  return true;
}

bool ConditionNumber(const Condition& condition, const std::string& column, double* out) {
  auto it = condition.find(column);
  return it != condition.end() && ParseConditionNumber(it->second, out);
}

std::string DescribeCondition(const Condition& condition) {
  std::string text;
  for (const auto& [column, cell] : condition) text += (text.empty() ? "" : ", ") + column + "=" + cell;
  return text;
}

}  // namespace demcal::calibrate
