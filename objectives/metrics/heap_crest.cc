#include "objectives/metrics/heap_crest.h"

namespace demcal::objectives {

double CrestDrop(const ReposeAngle& angle, double base_z_m) {
  if (!angle.ok || angle.flanks.empty()) return 0;
  double apex = 0;
  for (const FlankFit& f : angle.flanks) apex += f.intercept_m;
  apex /= static_cast<double>(angle.flanks.size());
  return apex - (base_z_m + angle.heap_height_m);
}

}  // namespace demcal::objectives
