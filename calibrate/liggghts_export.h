#pragma once
// A particle model's materials and pair table in LIGGGHTS-PUBLIC 3.8's conventions: the
// `fix property/global` lines of a granular input deck and the contact law of its `pair_style
// gran` and `fix wall/gran` lines. One atom type per demcal material, in the model's order.
// Hertz–Mindlin with tangential history is `model hertz tangential history`; Young's moduli are
// written as demcal holds them (E = 2G(1 + ν) from the file's shear modulus).
//
// Rolling friction (docs/export.md, "Rolling friction"): epsd and epsd2 are the same laws in
// both codes and map unchanged. demcal's cdt is EDEM's (a torque μr·Fn·R_i against each grain's
// own spin, on each grain of the contact); LIGGGHTS' cdt applies μr·Fn·R* against the relative
// spin ω_i − ω_j, equal and opposite on both grains, with R* = R_i R_j/(R_i + R_j) between
// grains and R* = R_i on a wall (LIGGGHTS-PUBLIC src/rolling_model_cdt.h). A coefficient is
// converted so the torque on a grain rolling over a resting one has the same size:
// particle–particle μr' = μr (R_i + R_j)²/(2 R_i R_j) (2 for equal spheres), particle–wall
// μr' = μr. The laws still differ (own vs relative spin), and that conversion is not enough to
// reproduce a heap (measured, docs/export.md), so cdt is refused unless the caller asks for the
// torque conversion (LiggghtsLawOptions::cdt_torque_conversion).
//
// Adhesion: LIGGGHTS-PUBLIC has no JKR; its `cohesion sjkr` adds k·A (A the overlap's contact
// area, k an energy density in J/m³), another law. A pair with Γ > 0 is refused, or, with
// sjkr_approximation, written as sjkr with k = F_c/(π a0²): JKR's pull-off force F_c = 3πΓR*
// (work of adhesion 2Γ) spread over its zero-load contact area, a0³ = 9πΓR*²/E*.
//
//   LiggghtsLaw law;  std::string error;
//   if (!ConvertToLiggghts(model, ContactUseOf(model, wall_materials), {}, &law, &error)) ...;
//   out << LiggghtsMaterialLines(model, law);
//
// Values are written in the shortest form that reads back to the same double.
#include <string>
#include <vector>

#include "core/scene/scene.h"

namespace demcal::calibrate {

// Which contacts each material pair takes part in, and the particle sizes they see.
struct ContactUse {
  std::vector<double> mean_radius_m;  // per material: number-mean radius of its species (0: none)
  std::vector<bool> wall;             // per material: some wall is made of it
};

// From the model's species; `wall_materials` lists the materials walls are made of. Without a
// wall list (a bare material include) every material no species uses is taken as a wall's.
ContactUse ContactUseOf(const core::Scene& model, const std::vector<int>& wall_materials);
ContactUse ContactUseOf(const core::Scene& model);

struct LiggghtsLawOptions {
  bool cdt_torque_conversion = false;  // export cdt with the torque conversion (not reproducing)
  bool sjkr_approximation = false;     // export JKR pairs as sjkr (another law)
};

// The model in LIGGGHTS' conventions: the contact law and the matrices (row-major, n × n).
struct LiggghtsLaw {
  std::string model;                        // "model hertz tangential history rolling_friction cdt"
  std::vector<double> rolling_coefficient;  // LIGGGHTS' μr per pair (converted where needed)
  std::vector<double> cohesion_energy_density_J_m3;  // sjkr k per pair; empty: no cohesion
  std::vector<std::string> notes;  // one line per conversion made, for the deck's comments
};

// particle–particle cdt factor: LIGGGHTS' μr over demcal's for grains of radii r_i, r_j.
double CdtParticleFactor(double radius_i_m, double radius_j_m);
// sjkr's cohesion energy density for Γ (J/m², EDEM convention) at E* (Pa) and R* (m).
double SjkrEnergyDensity(double gamma_J_m2, double effective_youngs_Pa, double effective_radius_m);

// False with *error naming the pair and the law when a pair cannot be written in LIGGGHTS'
// laws under `options`.
bool ConvertToLiggghts(const core::Scene& model, const ContactUse& use,
                       const LiggghtsLawOptions& options, LiggghtsLaw* law, std::string* error);

// The `fix property/global` lines (ids m1..m7) of `law` for `model`.
std::string LiggghtsMaterialLines(const core::Scene& model, const LiggghtsLaw& law);

// A stand-alone include (calibrated_params.liggghts): comments, atom types, the contact law as a
// comment, the property lines. A pair the conversion refuses is named in a comment and its
// property lines are left out, so the include cannot be used for it by mistake.
std::string LiggghtsMaterialInclude(const core::Scene& model,
                                    const std::vector<std::string>& comments);

}  // namespace demcal::calibrate
