#pragma once
// Seed streams: every stream number passed to DeriveSeed(seed, stream) (core/math/random.h) in
// one table, so each random consumer of a seed draws from its own stream and a new consumer can
// see which numbers are taken. Two consumers on one stream of the same seed would draw the same
// numbers (correlated packings, a floor that mirrors the index), and a changed number changes
// every result that depends on it: the values below are part of what makes runs bit-identical
// across versions, so never renumber one.
//
// A virtual experiment's seed is also its scene's seed, so the engine's streams (0, 1 + f for
// fill f, 1000 + f for factory f) and the experiments' (77 and the ASCII-tagged numbers 0x5345
// "SE", 0x464c "FL", 0x7261636b "rack", 0x706c616365 "place") come from one seed and must not
// meet. The tagged numbers lie far above the engine's; 77 is clear of them for scenes of at most
// 76 fills (the experiments add none).
//
// Usage:
//   core::Rng rng(core::DeriveSeed(scene.seed, core::kFactoryStreamBase + f));
#include <cstdint>

namespace demcal::core {

// --- the engine (core/simulation) --------------------------------------------------------------

// The sizes of the scene's initial particles (those listed with no diameter of their own).
constexpr uint64_t kInitialParticlesStream = 0;
// Fill f draws from kFillStreamBase + f: each fill packs its region with its own numbers, so
// adding a fill does not reshuffle the others.
constexpr uint64_t kFillStreamBase = 1;
// Factory f draws from kFactoryStreamBase + f for the whole run (positions, sizes, species of
// every batch); far above the fills so a scene's fill and factory streams never meet.
constexpr uint64_t kFactoryStreamBase = 1000;

// --- replicates (objectives/common/replicates.h) -----------------------------------------------

// Replicate r of an experiment runs with the seed DeriveSeed(base_seed, kReplicateStreamBase + r),
// the same for every candidate parameter set (common random numbers). Offset from the engine's
// low streams so a replicate's seed is not the seed of the initial particles or a fill of a run
// at the base seed itself.
constexpr uint64_t kReplicateStreamBase = 1000;

// --- the virtual experiments (objectives/) ------------------------------------------------------

// The random sphere layout of a glued (rough) base under a heap, drawn apart from the packing the
// same seed gives the feed.
constexpr uint64_t kGluedBaseStream = 77;
// The hopper's placed fill (discharge): the shuffle of species over lattice sites and the jitter.
constexpr uint64_t kHopperPlacementStream = 0x706c616365;  // "place"
// Which inserted grains a granule recorder follows (the phase of its every-stride-th pick), drawn
// apart from the packing.
constexpr uint64_t kGranuleSampleStream = 0x7261636b;  // "rack"
// The random-mixture sampling behind a segregation index (SegregationOptions::random).
constexpr uint64_t kSegregationIndexStream = 0x5345;  // "SE"
// The random-mixture floor the segregation index is compared with: independent of the index's
// own sampling, else the floor would share its noise.
constexpr uint64_t kSegregationFloorStream = 0x464c;  // "FL"

// --- inside the segregation index (objectives/metrics/segregation_index.cc) ---------------------

// From the index's seed: species s samples its number basis on stream kSpeciesStreamStride * s,
// and its mass basis on stream kMassBasisSubstream of that species' stream.
constexpr uint64_t kSpeciesStreamStride = 2;
constexpr uint64_t kMassBasisSubstream = 1;

}  // namespace demcal::core
