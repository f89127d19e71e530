#include "experiments/segregation/mechanism/axis_offset.h"

#include <cmath>

namespace demcal::objectives {

std::optional<double> AxisOffset(const Snapshot& heap, int tracked, int major) {
  double mass = 0, moment = 0;
  for (const Grain& g : heap.grains) mass += g.mass_kg, moment += g.mass_kg * g.position_m.x;
  if (!(mass > 0)) return std::nullopt;
  const double centre = moment / mass;
  double tracked_sum = 0, major_sum = 0;
  int tracked_n = 0, major_n = 0;
  for (const Grain& g : heap.grains) {
    const double distance = std::abs(g.position_m.x - centre);
    if (g.species == tracked) tracked_sum += distance, ++tracked_n;
    if (g.species == major) major_sum += distance, ++major_n;
  }
  if (tracked_n == 0 || major_n == 0 || !(major_sum > 0)) return std::nullopt;
  return (tracked_sum / tracked_n) / (major_sum / major_n) - 1;
}

}  // namespace demcal::objectives
