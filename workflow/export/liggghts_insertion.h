#pragma once
// The particles of a scene in a LIGGGHTS-PUBLIC 3.8 deck (docs/export.md):
//  - particle templates: one `fix particletemplate/sphere` (or `/multisphere` for a clump, its
//    member spheres scaled as demcal scales the shape: unit volume-equivalent diameter × d) per
//    species and size class. A fixed size is one class; a sieve cut (uniform in diameter) is
//    kSizeClasses equal-number classes at their centres; a table keeps its rows;
//  - one `fix particledistribution/discrete/numberbased` per factory or fill, its number
//    fractions from the mass fractions of the species and their mean masses;
//  - factories as `fix insert/rate/region` (mass rate, total mass, batch interval in steps,
//    velocity, a box or z-cylinder region), fills as `fix insert/pack` (count, once);
//  - explicitly placed particles (a glued base) in a `read_data` file, fixed ones in group
//    `fixed` (not integrated, their pairs excluded from the neighbour list).
// Atom type = demcal material index + 1. Refused (false with *error naming the item): moving
// or heap-following insertion regions, placed clumps, and clumps moving beside single spheres.
#include <string>
#include <vector>

#include "core/scene/scene.h"

namespace demcal::workflow {

inline constexpr int kSizeClasses = 5;

struct LiggghtsParticles {
  std::string data_file;  // contents of the read_data file ("" when no placed particles)
  std::string commands;   // templates, distributions, insertion fixes
  bool clumps = false;    // some template is a multisphere (needs `fix multisphere`)
  int64_t placed = 0;     // particles in the data file (ids 1..placed)
  int64_t fixed = 0;      // of which fixed
};

// Insertion fixes start at the deck's current step; `timestep_s` turns times into steps.
bool LiggghtsParticleCommands(const core::Scene& scene, double timestep_s, LiggghtsParticles* out,
                              std::string* error);

}  // namespace demcal::workflow
