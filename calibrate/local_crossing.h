#pragma once
// LocalCrossing: where one noisy observable crosses its measurement, from a weighted straight
// line through the candidates around the crossing, for a one-parameter, one-target search that
// ended without a single candidate within noise. A root finder on a noisy observable (bracket,
// optimiser_bracket.cc) can bracket the measurement between candidates whose own heaps scatter
// more than the measurement's uncertainty, and then no one candidate matches however close it
// lies; pooling the candidates near the crossing in one local fit is the standard remedy of
// stochastic root finding (a local regression, as LOESS pools neighbours; Cleveland 1979).
//
// Window: the widest set of candidates around the crossing that a straight line fits. It starts
// as every candidate, and while the line misfits, the candidate farthest (in the parameter) from
// the middle of the sign changes is dropped; the candidates between the outermost pair of
// neighbours whose residuals change sign are never dropped. The bracket search puts most of its
// candidates near the crossing, so the window pools them; where the observable bends, the far
// ones leave. Fit: r = α + β(u − ū), weights 1/(noise² + floor²), centred on the weighted mean ū
// so that α and β are uncorrelated. Thresholds, each with its reason:
//  - at least 3 candidates: one degree of freedom to test the line;
//  - the line must fit its points: P(χ²_dof > χ²) ≥ kAdequacyLevel = 0.01, the customary 1 %
//    test; a line that misfits at 1 % is not a local description (a jump, or curvature);
//  - covariance × max(1, χ²/dof), as ResponseSurface (never below what the stated noise
//    implies; larger when the line misfits within the test);
//  - |β| / σ_β ≥ kSlopeZ = 2 (95 % two-sided): below it the sign of the slope, and with it the
//    crossing, is not resolved;
//  - the crossing must lie inside the window (interpolation only).
// The crossing u* = ū − α/β. The line's own standard error at u*, σ_r = sqrt(σ_α² + (u* − ū)²
// σ_β²), in units of the measurement's uncertainty; σ_u by the delta method,
// sqrt(1 + σ_r²) / |β|: the crossing moves with the line and with the measurement (the 1), as a
// calibrated parameter's σ counts both (calibration.h). `matched`: fitted and σ_r ≤
// kMatchNoise, the precision rule of a single candidate's match (optimiser.h): the pooled
// simulation is at least as precise as the measurement, and its value at u* equals it.
//
//   LocalCrossing c = FitLocalCrossing(samples);
//   if (c.matched) use(c.unit, c.unit_sigma);
//
// Thread-safety: a plain value and a pure function.
#include <string>
#include <vector>

#include "calibrate/response_surface.h"

namespace demcal::calibrate {

inline constexpr double kAdequacyLevel = 0.01;
inline constexpr double kSlopeZ = 2.0;

struct LocalCrossing {
  bool fitted = false;   // a crossing inside the window from an adequate line
  bool matched = false;  // fitted, and the line at the crossing as precise as the measurement
  std::string message = "not fitted: a candidate matched within noise, or the search has more "
                        "than one parameter or target";
  int points = 0;               // candidates in the window
  double unit = 0;              // u*, the unit-cube parameter where the line crosses 0
  double unit_sigma = 0;        // its standard error (delta method; line and measurement)
  double residual_sigma = 0;    // the line's standard error at u*, standardised
  double slope = 0, slope_sigma = 0;  // dr/du and its standard error
  double chi_square = 0;
  int dof = 0;
  double window_min = 0, window_max = 0;  // the window's span (unit cube)
};

// `samples`: every candidate evaluated (unit of size 1, one residual); failed ones are skipped.
LocalCrossing FitLocalCrossing(const std::vector<Sample>& samples, double noise_floor = 0.01);

}  // namespace demcal::calibrate
