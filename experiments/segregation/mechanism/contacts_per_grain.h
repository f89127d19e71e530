#pragma once
// Contacts per grain between two species in a heap (Alizadeh et al. 2018, section 3.5): how many
// grains of `partner` touch a grain of `species`, on average over the grains of `species`. The
// paper's excessive-adhesion mechanism is EP seeds covered by BP that avalanche together; the
// EP–BP contacts per EP grain measure how much BP an EP grain carries.
//
// Two grains touch when any member sphere of one and any of the other have centres closer than
// (1 + gap_fraction)(r_i + r_j): at rest, contacting spheres overlap by a small fraction of their
// radii at the simulation stiffness, and gap_fraction admits the contacts that a settled heap
// holds open by a hair. Each partner grain counts once per grain of `species`, whatever the
// number of its spheres that touch (a clump touching with two spheres is one contact).
#include <optional>

#include "objectives/common/snapshot.h"

namespace demcal::objectives {

struct ContactOptions {
  double gap_fraction = 0.01;
};

// Mean over the grains of `species` of the number of `partner` grains touching each; nullopt
// when the snapshot holds no grain of `species`. species == partner counts like neighbours.
std::optional<double> ContactsPerGrain(const Snapshot& heap, int species, int partner,
                                       const ContactOptions& options);

}  // namespace demcal::objectives
