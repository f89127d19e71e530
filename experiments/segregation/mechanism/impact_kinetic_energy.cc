#include "experiments/segregation/mechanism/impact_kinetic_energy.h"

namespace demcal::objectives {

std::optional<double> AfterImpactSpecificKineticJKg(const TrackedGranule& granule,
                                                    const AfterImpactOptions& options) {
  if (!granule.impact_sample) return std::nullopt;
  const std::vector<GranuleSample>& samples = granule.track.samples;
  const size_t first = static_cast<size_t>(*granule.impact_sample);
  if (first >= samples.size()) return std::nullopt;
  const double end_s = samples[first].time_s + options.window_s;
  double sum = 0;
  int n = 0;
  for (size_t k = first; k < samples.size() && samples[k].time_s <= end_s; ++k, ++n)
    sum += samples[k].SpecificKineticEnergyJPerKg();
  return sum / n;  // n ≥ 1: the impact sample itself is in the window
}

}  // namespace demcal::objectives
