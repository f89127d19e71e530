#pragma once
// The fill of a discharge hopper (discharge_experiment.h): where the feed enters, how many
// grains a placed fill holds, whether the fill fits in the hopper and, once discharged, in the
// catch bin, and the bulk density of the settled fill (Beverloo's ρ_b).
//
// Geometry as in discharge_experiment.h: orifice plane z = 0, hopper axis = z axis. SI units.
#include <cstdint>
#include <ostream>

#include "core/insertion_region.h"
#include "core/particles.h"
#include "core/scene.h"
#include "objectives/discharge_experiment.h"

namespace demcal::objectives {

// A poured fill: a cylinder (feed_diameter_m) just above the hopper's rim, 6 grains tall.
// A placed fill: a box inside the rim's footprint, tall enough to hold the feed at a solid
// fraction of 20% (random placement finds room up to about 30%).
core::InsertionRegion FeedRegion(const core::Scene& model, const DischargeSettings& settings);

// Grains of `component` in a placed fill: its mass over the species' mean grain mass.
int64_t PlacedCount(const core::Scene& model, const Feed& feed, const FeedComponent& component);

// Inside volume of the hopper (cone frustum + cylinder), m³.
double HopperVolume(const HopperGeometry& hopper);

// The feed at a solid fraction of 0.6 must fill at most 90% of the hopper and, discharged into a
// heap, at most 40% of the catch bin below the orifice (so the heap stays clear of the orifice).
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
