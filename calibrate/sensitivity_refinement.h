#pragma once
// Sensitivity refinement: when the calibration ends with a parameter σ = +∞ only because the
// sensitivities were estimated from too few, too noisy runs (a singular value of J below the
// noise floor of its own entries, jacobian_svd.h), a few more candidates around the best give the
// response surface (response_surface.h) the points it lacks. σ = +∞ should say "the data cannot
// tell", never "we did not look closely enough".
//
// Round r asks for the stencil best ± h_r·e_k in the unit cube, h_r = min(0.25, 2^(r+1)·h0),
// h0 = clamp(4·noise_max/√12, 0.01, 0.25): the optimisers' own finite-difference step
// (optimiser_ceres.cc) doubled per round, so no point repeats one already run (a repeat would be
// read back from the journal with the same answer) and the signal over the step grows while the
// noise per point stays. A side beyond the bounds is dropped. The stencil points are then re-run
// at CalibrationOptions::max_replicate_factor times their replicates (where the evaluator can add
// replicates): the noise of a sensitivity falls as 1/√n. Rounds stop when every σ is finite, at
// CalibrationOptions::sensitivity_rounds, or when a round would exceed max_evaluations.
//
// Thread-safety: a pure function.
#include <vector>

namespace demcal::calibrate {

// The finite-difference step in the unit cube for a simulation noise noise_max (sem / u):
// clamp(4·noise_max/√12, 0.01, 0.25) (why: optimiser_ceres.cc). Shared with the ceres optimiser.
double FiniteDifferenceStep(double noise_max);

// The unit-cube points of refinement round `round` (0, 1, ...) around `best_unit`; noise_max is
// the largest simulation noise (sem / u) at the best.
std::vector<std::vector<double>> RefinementStencil(const std::vector<double>& best_unit,
                                                   double noise_max, int round);

}  // namespace demcal::calibrate
