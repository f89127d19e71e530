#pragma once
// SceneFingerprint: what a checkpoint remembers of the scene it was written for, as named parts
// each with a 64-bit FNV-1a digest, so a restart into another scene is refused with the parts
// that differ ("walls", "time step", ...) rather than run on state that does not belong to it.
//
// Parts: materials, species (size distributions, clump shapes), contact parameters (pair table,
// rolling model), walls (name, material, shape and geometry including mesh vertices, sides, load
// point), wall motion (velocity, start, end), domain (box, periodic axes), gravity, initial
// particles (explicit particles and fills), factories, seed, time step (the resolved Δt) and
// neighbour skin (the resolved skin). Not part of it: time.duration_s (a restart may extend a
// run), max_wall_time_s and the output settings.
//
// Doubles are hashed by their bits: the fingerprint is for the same build and machine type, like
// the checkpoint. A new physics field in Scene must be added here (tests/core/scene_fingerprint
// checks that each part reacts to a change).
#include <cstdint>
#include <string>
#include <vector>

#include "core/scene/scene.h"

namespace demcal::core {

struct FingerprintPart {
  std::string name;
  uint64_t digest = 0;
};

// `timestep_s` and `skin_m`: the values the simulation resolved from the scene.
std::vector<FingerprintPart> SceneFingerprint(const Scene& scene, double timestep_s,
                                              double skin_m);

// The names of the parts of `stored` that differ from `current` (a part missing on either side
// counts as differing), joined by ", ", leaving out those named in `ignore`; empty if they match.
std::string DifferingParts(const std::vector<FingerprintPart>& stored,
                           const std::vector<FingerprintPart>& current,
                           const std::vector<std::string>& ignore = {});

}  // namespace demcal::core
