#pragma once
// InteractionTable: the per-(material, material) contact parameters of the paper's Table 1
// (sliding friction, rolling friction, restitution, interfacial energy) and sjkr's cohesion
// energy density, with the effective elastic constants derived from the two materials. Resolved
// once at setup into a dense symmetric matrix so the contact loop does one indexed load per
// contact, no strings.
//
// Thread-safety: immutable after Resolve(); safe to read from any number of threads.
#include <string>
#include <vector>

#include "core/materials/material.h"

namespace demcal::core {

// What the user specifies for a pair of materials.
struct PairParameters {
  double sliding_friction = 0.5;          // μ_s, Coulomb coefficient, >= 0
  double rolling_friction = 0.0;          // μ_r, dimensionless (EPSD: tan of max slope), >= 0
  double restitution = 0.5;               // e in (0, 1]
  double interfacial_energy_J_m2 = 0.0;   // Γ, EDEM convention (work of adhesion w = 2Γ), >= 0
  // k of LIGGGHTS' cohesion sjkr (force k·A while overlapping, core/contact/sjkr.h), >= 0
  double cohesion_energy_density_J_m3 = 0.0;
};

// What the contact loop uses for a pair of materials (docs/physics.md §1.1).
struct ResolvedPair {
  double effective_youngs_Pa = 0;  // E*: 1/E* = (1-ν_i²)/E_i + (1-ν_j²)/E_j
  double effective_shear_Pa = 0;   // G*: 1/G* = 2(2-ν_i)(1+ν_i)/E_i + 2(2-ν_j)(1+ν_j)/E_j
  double beta = 0;                 // ln e / sqrt(ln² e + π²), <= 0
  double sliding_friction = 0;
  double rolling_friction = 0;
  double interfacial_energy_J_m2 = 0;
  double jkr_adhesion_length = 0;  // k = sqrt(4πΓ/E*) (m^½), JKR's δ(a) = a²/R* − k√a; 0 without Γ
  double tangential_damping_ratio = 0;  // sqrt(S_t/S_n) = sqrt(4G*/E*): c_t = c_n × this
  double cohesion_energy_density_J_m3 = 0;  // sjkr's k (J/m³); 0 without sjkr cohesion
};

// A resolved pair with its derived constants (the one way to build one).
ResolvedPair MakeResolvedPair(double effective_youngs_Pa, double effective_shear_Pa, double beta,
                              double sliding_friction, double rolling_friction,
                              double interfacial_energy_J_m2,
                              double cohesion_energy_density_J_m3 = 0);

class InteractionTable {
 public:
  InteractionTable() = default;
  // `pairs` is a full symmetric n x n matrix over `materials` (row-major).
  InteractionTable(const std::vector<Material>& materials, const std::vector<PairParameters>& pairs);

  int MaterialCount() const { return n_; }
  const ResolvedPair& Get(int material_i, int material_j) const {
    return resolved_[material_i * n_ + material_j];
  }

 private:
  int n_ = 0;
  std::vector<ResolvedPair> resolved_;
};

double BetaFromRestitution(double restitution);

}  // namespace demcal::core
