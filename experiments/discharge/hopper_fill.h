#pragma once
// The fill of a discharge hopper (discharge_experiment.h): where the feed enters, how many
// grains a placed fill holds, whether the fill fits in the hopper and, once discharged, in the
// catch bin, and the bulk density of the settled fill (Beverloo's ρ_b).
//
// Geometry as in discharge_experiment.h: orifice plane z = 0, hopper axis = z axis. SI units.
#include <cstdint>
#include <ostream>
#include <vector>

#include "core/insertion/insertion_region.h"
#include "core/bodies/particles.h"
#include "core/scene/scene.h"
#include "experiments/discharge/discharge_experiment.h"

namespace demcal::objectives {

// A poured fill: the factory's region, a cylinder (feed_diameter_m) just above the hopper's rim,
// 6 grains tall.
core::InsertionRegion FeedRegion(const core::Scene& model, const DischargeSettings& settings);

// A placed fill: the feed's grains at t = 0 on a cubic lattice of spacing 1.1 largest diameters
// d (solid fraction ≈ 0.39, so the fill collapses by only about a third of its height and
// settles in a fraction of the time a fill dropped from above the rim takes), filling the hopper
// from the closed gate up, every centre at least 0.55 d from the gate, cone and cylinder; layers
// go on above the rim inside its footprint if needed. Each site is jittered by up to ±4% of the
// spacing and the species are shuffled over the sites in the feed's proportions (PlacedCount),
// both from `seed`.
std::vector<core::ParticleSpec> PlacedFill(const core::Scene& model,
                                           const DischargeSettings& settings, uint64_t seed);

// Highest point a fill starts from: the top of the pour region, or of the placed lattice.
double FillTopM(const core::Scene& model, const DischargeSettings& settings);

// When the fill is complete: the end of the pour, or the collapse of a placed lattice (its top
// falls by about a third of the fill height).
double FillEndS(const core::Scene& model, const DischargeSettings& settings);

// Grains of `component` in a placed fill: its mass over the species' mean grain mass.
int64_t PlacedCount(const core::Scene& model, const Feed& feed, const FeedComponent& component);

// Inside volume of the hopper (cone frustum + cylinder), m³.
double HopperVolume(const HopperGeometry& hopper);

// The feed at a solid fraction of 0.6 must fill at most 90% of the hopper and, the part of it that
// is discharged (analysis.discharge_fraction), at most 40% of the catch bin below the orifice (so
// the heap stays clear of the orifice).
// False with a message naming the fields.
bool FitsInHopper(const core::Scene& model, const DischargeSettings& settings, std::ostream* os);
bool FitsInCatchBin(const core::Scene& model, const DischargeSettings& settings,
                    std::ostream* os);

// Bulk density (kg/m³) of the grains in the hopper: mass of the grain centres inside a probe over
// its volume. The probe is the hopper's inside kept one largest diameter `d_m` from the wall,
// from 2 d above the orifice up to the median height of the grains above the orifice (below the
// fill's free surface). 0 when the probe is empty or has no volume.
double HopperBulkDensity(const core::Particles& particles, const HopperGeometry& hopper,
                         double d_m);

}  // namespace demcal::objectives
