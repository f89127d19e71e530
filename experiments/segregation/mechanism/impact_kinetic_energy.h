#pragma once
// Specific kinetic energy of a tracked granule after its first impact (Alizadeh et al. 2018,
// section 3.5, Fig. 19): the mean of ½v² (J/kg) over the samples in the window_s after the impact
// sample (the impact sample included). The paper's coated EP lose nearly all their energy at the
// first impact and stay where they land; uncoated EP keep some and roll or bounce on. The peak
// before the impact (TrackedGranule::peak_specific_kinetic_J_kg) is set by the fall height and
// says nothing about the contact; this one does.
#include <optional>

#include "experiments/segregation/segregation_experiment.h"

namespace demcal::objectives {

struct AfterImpactOptions {
  // A few sampling intervals (2 ms by default): long enough to average over a bounce, short
  // against the ~0.1 s an avalanching grain takes to run down the heap.
  double window_s = 0.02;
};

// Mean ½v² (J/kg) over the samples with impact time ≤ t ≤ impact time + window_s; nullopt
// without an impact.
std::optional<double> AfterImpactSpecificKineticJKg(const TrackedGranule& granule,
                                                    const AfterImpactOptions& options);

}  // namespace demcal::objectives
