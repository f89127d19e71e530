#pragma once
// `demcal cohesion`: the Cohesion number of a coated granule and the Γ that keeps it at a softer
// simulation stiffness (calibrate/cohesion_scaling.h, where the R* and E* convention is stated).
// Defaults are the paper's coated EP (Alizadeh et al. 2018, section 2.5.2).
#include "apps/command.h"

namespace demcal::apps {

Command AddCohesionCommand(CLI::App& parent);

}  // namespace demcal::apps
