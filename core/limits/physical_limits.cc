#include "core/limits/physical_limits.h"

#include <sstream>

namespace demcal::core::limits {

std::string Limit::Text() const {
  std::ostringstream os;  // default stream precision: 6 significant digits, as every message
  os << (lo_open ? "(" : "[") << lo << ", " << hi << (hi_open ? ")" : "]");
  return os.str();
}

}  // namespace demcal::core::limits
