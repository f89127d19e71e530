#include "experiments/segregation/mechanism/mechanism_observables.h"

#include <algorithm>

#include "experiments/segregation/mechanism/axis_offset.h"
#include "experiments/segregation/mechanism/contacts_per_grain.h"
#include "experiments/segregation/mechanism/impact_kinetic_energy.h"
#include "experiments/segregation/mechanism/landing_depth.h"

namespace demcal::objectives {
namespace {

// The mean over the tracked granules that have a value; nullopt when none has.
template <typename Of>
std::optional<double> MeanOverTracked(const SegregationRun& run, Of of) {
  double sum = 0;
  int n = 0;
  for (const TrackedGranule& g : run.tracked)
    if (const std::optional<double> v = of(g)) sum += *v, ++n;
  return n > 0 ? std::optional<double>(sum / n) : std::nullopt;
}

std::optional<double> LandingDepth(const SegregationRun& run, const SegregationSettings&) {
  return MeanOverTracked(run, [](const TrackedGranule& g) { return LandingDepthM(g, {}); });
}

std::optional<double> AfterImpact(const SegregationRun& run, const SegregationSettings&) {
  return MeanOverTracked(
      run, [](const TrackedGranule& g) { return AfterImpactSpecificKineticJKg(g, {}); });
}

std::optional<double> MajorContacts(const SegregationRun& run, const SegregationSettings& s) {
  const int major = MajorSpecies(s);
  if (major < 0) return std::nullopt;
  return ContactsPerGrain(run.heap, s.TrackedSpecies(), major, {});
}

std::optional<double> Offset(const SegregationRun& run, const SegregationSettings& s) {
  const int major = MajorSpecies(s);
  if (major < 0) return std::nullopt;
  return AxisOffset(run.heap, s.TrackedSpecies(), major);
}

}  // namespace

const std::vector<MechanismObservable>& MechanismObservables() {
  static const std::vector<MechanismObservable> list = {
      {"tracked_landing_depth_m",
       "tracked granules: depth of the centre below the local heap surface at the first rest "
       "after the first impact (> 0 buried, about -r lying on the surface; Fig. 17)",
       &LandingDepth},
      {"tracked_after_impact_specific_kinetic_J_kg",
       "tracked granules: mean 1/2 v^2 over the 20 ms after the first impact (Fig. 19)",
       &AfterImpact},
      {"tracked_major_contacts_per_grain",
       "settled heap: grains of the major species touching each grain of the tracked species "
       "(EP-BP contacts per EP grain in the paper's mixture)",
       &MajorContacts},
      {"tracked_axis_offset_fraction",
       "settled heap: the tracked species' mean distance from the heap's axis over the major "
       "species', minus 1 (< 0 in the centre, > 0 toward the toes; section 3.5)",
       &Offset},
  };
  return list;
}

int MajorSpecies(const SegregationSettings& settings) {
  const std::vector<FeedComponent>& c = settings.feed.components;
  if (c.empty()) return -1;
  return std::max_element(c.begin(), c.end(), [](const FeedComponent& a, const FeedComponent& b) {
           return a.mass_fraction < b.mass_fraction;
         })->species;
}

}  // namespace demcal::objectives
