#include "calibrate/observable_registry.h"

#include <sstream>

#include "objectives/common/input_limits.h"

namespace demcal::calibrate {

// Ranges are what is physically possible, not what is typical: a repose angle lies in [0, 90]
// deg by definition; lengths, times and rates are positive and below sizes no bench test
// reaches (100 m, 10^6 s, 10^6 kg/s); no granular bulk is denser than osmium (22,590 kg/m³).
const std::vector<ObservableInfo>& RegisteredObservables() {
  static const std::vector<ObservableInfo> observables = {
      {"angle_deg", "deg", 0, 90, "angle of repose of the settled heap (flank fit, paper Fig. 5)"},
      {"heap_height_m", "m", 0, 100, "height of the settled heap above its base"},
      {"crest_drop_m", "m", -100, 100,
       "how far the heap top lies below the apex of its fitted flanks (> 0: rounded crest, as "
       "cohesion makes it; < 0: a peak steeper than the flanks)"},
      {"discharge_time_s", "s", 0, 1e6, "time to discharge the funnel (gate opening to "
                                        "discharge_fraction of the fill out)"},
      {"mass_flow_kg_s", "kg/s", 0, 1e6, "steady mass flow rate through the orifice"},
      {"bulk_density_kg_m3", "kg/m3", 0, 22590, "bulk density of the settled fill"},
  };
  return observables;
}

const ObservableInfo* FindObservable(const std::string& name) {
  for (const ObservableInfo& o : RegisteredObservables())
    if (o.name == name) return &o;
  return nullptr;
}

std::vector<std::string> ObservableNames() {
  std::vector<std::string> names;
  for (const ObservableInfo& o : RegisteredObservables()) names.push_back(o.name);
  return names;
}

std::string ObservableInfo::RangeText() const {
  std::ostringstream out;
  out << "[" << min << ", " << max << "] " << unit;
  return out.str();
}

double ObservableInfo::MinUncertainty() const {
  return objectives::limits::kMinUncertaintyFraction * (max - min);
}

std::string ObservableInfo::UncertaintyRangeText() const {
  std::ostringstream out;
  out << "[" << MinUncertainty() << ", " << max - min << "] " << unit;
  return out.str();
}

}  // namespace demcal::calibrate
