#pragma once
// LiggghtsMaterialInclude: a particle model's materials and pair table as a LIGGGHTS-PUBLIC
// include file (the `fix property/global` lines of a granular input deck), so a DEM engineer
// can run the calibrated parameters in LIGGGHTS. One atom type per demcal material, in the
// model's order. Hertz–Mindlin with tangential history is LIGGGHTS' `model hertz tangential
// history`; demcal's rolling models map by name (cdt, epsd, epsd2). LIGGGHTS-PUBLIC has no JKR
// model (its sjkr cohesion takes an energy density in J/m³, a different law), so Γ is listed in
// comments, not converted.
//
//   std::string deck = LiggghtsMaterialInclude(calibrated_model, {"study: ...", "fidelity: ..."});
//
// Values are written in the shortest form that reads back to the same double.
#include <string>
#include <vector>

#include "core/scene/scene.h"

namespace demcal::calibrate {

std::string LiggghtsMaterialInclude(const core::Scene& model, const std::vector<std::string>& comments);

}  // namespace demcal::calibrate
