#pragma once
// The F distribution's upper tail, for the evidence of an effect when the discrepancy floor is
// estimated from the same residuals (evidence.h): with the variance's scale estimated on ν2
// degrees of freedom, an improvement Δχ²/k is compared with F(k, ν2), not with χ²_k/k (which
// would treat the estimated scale as known and over-reject on a dozen observations).
// P(F(d1, d2) > f) = I_{d2/(d2 + d1·f)}(d2/2, d1/2), the regularised incomplete beta function by
// its continued fraction (Press et al., Numerical Recipes 3rd ed. §6.4; ~1e-12 relative).
//
//   FSurvival(5.59, 1, 7);  // ≈ 0.05
//
// Thread-safety: pure functions.
namespace demcal::diagnose {

// I_x(a, b), a, b > 0, x in [0, 1].
double RegularisedIncompleteBeta(double a, double b, double x);
// P(F(d1, d2) > f); 1 for f <= 0. d1, d2 > 0.
double FSurvival(double f, double d1, double d2);

}  // namespace demcal::diagnose
