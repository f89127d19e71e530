#include "experiments/segregation/funnel_geometry.h"

namespace demcal::objectives {

double FunnelSettings::OrificeDiameterM(double max_grain_diameter_m) const {
  if (!ScalesWithFidelity()) return orifice_diameter_m;
  return effective_orifice_diameter_m + beverloo_k * max_grain_diameter_m;
}

}  // namespace demcal::objectives
