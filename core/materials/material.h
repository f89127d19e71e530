#pragma once
// Material and species definitions (SI units). A Material is what a surface is made of (elastic
// constants, density); a Species is a kind of particle: a material plus a size distribution.
// Walls reference materials too, so every contact is a (material, material) pair whose
// friction, restitution and adhesion live in the InteractionTable.
#include <string>
#include <vector>

#include "core/math/vec3.h"

namespace demcal::core {

struct Material {
  std::string name;
  double youngs_modulus_Pa = 0;  // E; give either E or G in input, the other is derived
  double poisson_ratio = 0.25;   // ν in (-1, 0.5)
  double density_kg_m3 = 0;      // only needed for particle materials

  double ShearModulus() const { return youngs_modulus_Pa / (2.0 * (1.0 + poisson_ratio)); }
  static double YoungsFromShear(double shear_modulus_Pa, double poisson_ratio) {
    return 2.0 * shear_modulus_Pa * (1.0 + poisson_ratio);
  }
};

// How particle diameters of a species are drawn (all in metres).
struct SizeDistribution {
  enum class Kind { kFixed, kUniform, kTable };
  Kind kind = Kind::kFixed;
  double diameter_m = 0;                      // kFixed
  double min_diameter_m = 0, max_diameter_m = 0;  // kUniform (a sieve cut)
  std::vector<double> table_diameter_m;       // kTable: diameters ...
  std::vector<double> table_number_fraction;  // ... and their number fractions (sum to 1)

  double MaxDiameter() const;
  double MinDiameter() const;
  // Draws a diameter from a uniform variate u in [0, 1).
  double Sample(double u) const;
  // Number-weighted mean particle volume (m^3), used to turn masses into counts.
  double MeanVolume() const;
};

// A member sphere of a clumped-sphere particle shape, in any length unit and frame: the
// engine normalises the shape to unit equivalent-volume diameter, so `size` sets the scale.
struct ShapeSphere {
  Vec3 centre;
  double radius = 0;
};

struct Species {
  std::string name;
  int material = 0;  // index into Scene::materials
  SizeDistribution size;  // of the equivalent-volume diameter for clumps
  std::vector<ShapeSphere> clump_shape;  // empty: a plain sphere
};

}  // namespace demcal::core
