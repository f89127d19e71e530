#pragma once
// Tail probabilities of the distributions the calibration (the joint match, optimiser.h) and
// the diagnosis test against: the chi-square
// distribution (the sum of k squared standard normal residuals) and the standard normal.
// Regularised incomplete gamma by its series (x < a + 1) and Lentz's continued fraction
// (otherwise), as in Press et al., Numerical Recipes 3rd ed. §6.2; accurate to ~1e-12 relative.
// Pure functions, thread-safe.
//
//   ChiSquareSurvival(23.2, 10);    // P(χ²_10 > 23.2) ≈ 0.01
//   ChiSquareQuantile(0.99, 10);    // ≈ 23.21
//   NormalTwoSidedQuantile(0.01);   // ≈ 2.576: |z| beyond it has probability 0.01
namespace demcal::calibrate {

// Q(a, x) = Γ(a, x) / Γ(a), a > 0, x >= 0.
double RegularisedUpperGamma(double a, double x);
// P(χ²_dof > x); 1 for x <= 0. dof > 0 (need not be an integer).
double ChiSquareSurvival(double x, double dof);
// The x with P(χ²_dof <= x) = p, p in (0, 1) (bisection on the survival function).
double ChiSquareQuantile(double p, double dof);
// The z > 0 with P(|N(0,1)| > z) = alpha, alpha in (0, 1).
double NormalTwoSidedQuantile(double alpha);

}  // namespace demcal::calibrate
