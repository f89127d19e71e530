#include "experiments/segregation/mechanism/contacts_per_grain.h"

#include <set>

namespace demcal::objectives {

std::optional<double> ContactsPerGrain(const Snapshot& heap, int species, int partner,
                                       const ContactOptions& options) {
  // The spheres of each grain of `species`; a heap's minor species is a few hundred grains, so
  // comparing each of their spheres with every sphere is cheap beside the run that made it.
  std::vector<std::vector<const SurfaceSphere*>> mine(heap.grains.size());
  size_t grains = 0;
  for (const Grain& g : heap.grains) grains += g.species == species ? 1 : 0;
  if (grains == 0) return std::nullopt;
  for (const SurfaceSphere& s : heap.spheres)
    if (heap.grains[s.grain].species == species) mine[s.grain].push_back(&s);
  const double reach = 1 + options.gap_fraction;
  size_t contacts = 0;
  for (size_t a = 0; a < heap.grains.size(); ++a) {
    if (mine[a].empty()) continue;
    std::set<int> touching;
    for (const SurfaceSphere& other : heap.spheres) {
      if (other.grain == static_cast<int>(a) || heap.grains[other.grain].species != partner)
        continue;
      for (const SurfaceSphere* s : mine[a]) {
        const double limit = reach * (s->radius_m + other.radius_m);
        if (core::Norm2(s->position_m - other.position_m) < limit * limit) {
          touching.insert(other.grain);
          break;
        }
      }
    }
    contacts += touching.size();
  }
  return static_cast<double>(contacts) / static_cast<double>(grains);
}

}  // namespace demcal::objectives
