#pragma once
// Registry of rolling-resistance models. Adding a model = one header with an Apply() like
// RollingCdt's, one alternative in the variant and one line in MakeRollingModel().
#include <string>
#include <variant>
#include <vector>

#include "core/contact/rolling_cdt.h"
#include "core/contact/rolling_cdt_relative.h"
#include "core/contact/rolling_epsd.h"
#include "core/contact/rolling_none.h"

namespace demcal::core {

using RollingModel = std::variant<RollingNone, RollingCdt, RollingCdtRelative, RollingEpsd>;

// The load the rolling limit μ_r multiplies in an adhesive (JKR) contact (docs/physics.md §3).
//  kNet: the compressive force the contact transmits, max(0, F_JKR) (default). At zero load an
//    adhesive contact then has no rolling limit beyond the dashpot/spring, as a smooth sphere.
//  kRepulsive: the repulsive Hertz part 4E*a³/(3R*), as the Coulomb limit. At zero load this is
//    4× the pull-off force, so μ_r R* × (4 F_c) locks rolling: EP spheres (μ_r 0.25,
//    Γ 0.046 J/m², calibration fidelity) stand at 58.8 ± 1.8° and at Γ ≥ 0.1 J/m² as columns,
//    where "net" gives 35.9 ± 0.8° (Alizadeh et al. 2018, EDEM: 37.6°; bench/jkr_rolling_load.sh).
enum class JkrRollingLoad { kNet, kRepulsive };

struct RollingModelSpec {
  std::string name = "epsd2";   // none | cdt | cdt_relative | epsd | epsd2
  double epsd_damping_ratio = 0.3;  // η_r for "epsd", in [0, 1]
  std::string jkr_rolling_load = "net";  // net | repulsive (JkrRollingLoad)
};

inline const std::vector<std::string>& JkrRollingLoadNames() {
  static const std::vector<std::string> names = {"net", "repulsive"};
  return names;
}

// Returns false (and leaves `load` untouched) for an unknown name.
inline bool ParseJkrRollingLoad(const std::string& name, JkrRollingLoad* load) {
  if (name == "net") *load = JkrRollingLoad::kNet;
  else if (name == "repulsive") *load = JkrRollingLoad::kRepulsive;
  else return false;
  return true;
}

inline const std::vector<std::string>& RollingModelNames() {
  static const std::vector<std::string> names = {"none", "cdt", "cdt_relative", "epsd", "epsd2"};
  return names;
}

// Returns false (and leaves `model` untouched) for an unknown name.
inline bool MakeRollingModel(const RollingModelSpec& spec, RollingModel* model) {
  if (spec.name == "none") *model = RollingNone{};
  else if (spec.name == "cdt") *model = RollingCdt{};
  else if (spec.name == "cdt_relative") *model = RollingCdtRelative{};
  else if (spec.name == "epsd") *model = RollingEpsd::Epsd(spec.epsd_damping_ratio);
  else if (spec.name == "epsd2") *model = RollingEpsd::Epsd2();
  else return false;
  return true;
}

}  // namespace demcal::core
