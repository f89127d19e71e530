#pragma once
// Registry of rolling-resistance models. Adding a model = one header with an Apply() like
// RollingCdt's, one alternative in the variant and one line in MakeRollingModel().
#include <string>
#include <variant>
#include <vector>

#include "core/contact/rolling_cdt.h"
#include "core/contact/rolling_epsd.h"
#include "core/contact/rolling_none.h"

namespace demcal::core {

using RollingModel = std::variant<RollingNone, RollingCdt, RollingEpsd>;

struct RollingModelSpec {
  std::string name = "epsd2";   // none | cdt | epsd | epsd2
  double epsd_damping_ratio = 0.3;  // η_r for "epsd", in [0, 1]
};

inline const std::vector<std::string>& RollingModelNames() {
  static const std::vector<std::string> names = {"none", "cdt", "epsd", "epsd2"};
  return names;
}

// Returns false (and leaves `model` untouched) for an unknown name.
inline bool MakeRollingModel(const RollingModelSpec& spec, RollingModel* model) {
  if (spec.name == "none") *model = RollingNone{};
  else if (spec.name == "cdt") *model = RollingCdt{};
  else if (spec.name == "epsd") *model = RollingEpsd::Epsd(spec.epsd_damping_ratio);
  else if (spec.name == "epsd2") *model = RollingEpsd::Epsd2();
  else return false;
  return true;
}

}  // namespace demcal::core
