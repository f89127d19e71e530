#include "experiments/segregation/mechanism/landing_depth.h"

namespace demcal::objectives {

std::optional<double> LandingDepthM(const TrackedGranule& granule, const LandingOptions& options) {
  if (!granule.impact_sample) return std::nullopt;
  const std::vector<GranuleSample>& samples = granule.track.samples;
  for (size_t k = static_cast<size_t>(*granule.impact_sample); k < samples.size(); ++k) {
    const GranuleSample& s = samples[k];
    if (s.SpeedMS() < options.rest_speed_m_s && s.has_surface)
      return s.surface_height_m - s.position_m.z;
  }
  return std::nullopt;
}

}  // namespace demcal::objectives
