#pragma once
// Where the tracked species sits across the heap (Alizadeh et al. 2018, sections 3.1 and 3.5,
// Figs. 9, 17, 20): uncoated EP push into the heap where they land and collect in its central
// area, leaving the corners (the heap's toes) short of EP; coated EP ride the moving surface
// layer and spread over the whole heap, corners included; with excessive adhesion EP carry BP
// as agglomerates that avalanche and accumulate in the corners.
// Measured on the settled heap as the tracked grains' mean horizontal distance from the heap's
// axis relative to the major species' (BP's):
//
//   offset = mean_i |x_i − x_c| over the tracked grains / mean_j |x_j − x_c| over the major
//            grains − 1,
//
// x_c the heap's centre of mass along the box width (x, snapshot.h). 0 when the tracked grains
// spread across the heap as the bulk does (a random mixture, in expectation); < 0 nearer the
// axis (the centre); > 0 further out (the toes). A ratio, so the heap's size and the fidelity's
// size scale drop out. Its noise: for a heap whose cross-section is a triangle, a grain's
// |x − x_c| scatters by about 0.7 of its mean (a triangular density on [0, L]: mean L/3, sd
// L/√18), so n tracked grains per heap and m heaps give a standard error near 0.7/√(n m) when the
// major species is many; result.json reports the spread between heaps, which is what counts.
#include <optional>

#include "objectives/common/snapshot.h"

namespace demcal::objectives {

// The offset above; nullopt without a grain of either species.
std::optional<double> AxisOffset(const Snapshot& heap, int tracked, int major);

}  // namespace demcal::objectives
