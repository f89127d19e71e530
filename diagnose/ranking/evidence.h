#pragma once
// Evidence for one candidate effect: how much better the augmented model (base + effect, refit)
// fits than the base model, in the two standard currencies.
//  - Likelihood ratio: with Gaussian standardised residuals, −2 ln Λ = χ²_base − χ²_effect, which
//    under "the effect is absent" follows a chi-square with k degrees of freedom (Wilks 1938; k
//    the effect's parameters). p < significance: the improvement is beyond what fitting k more
//    parameters to noise gives.
//  - ΔBIC = χ²_effect − χ²_base + k·ln(n) (Schwarz 1978, n observations): the penalty k·ln n is
//    the statistics', not ours. Negative favours the effect; Kass & Raftery (1995) read
//    |ΔBIC| < 2 as "not worth more than a bare mention" and 2-6 as "positive"; two candidates
//    closer than kBicIndistinct = 6 ("strong") are not told apart.
//
//   Evidence e = EvidenceOf(chi2_base, chi2_effect, 1, 15, 0.01);
//
// With the discrepancy floor (discrepancy_floor.h) in the variance, EvidenceWithFloor: the floor
// φ is estimated from the effect's own fit (n − p − k degrees of freedom: the larger model's
// residuals, so the improvement is not counted into the floor that judges it), both fits'
// χ² are taken with it, Δχ² = χ²_base(φ) − χ²_effect(φ). When φ > 0 the variance's scale was
// estimated and Δχ²/k is compared with F(k, n − p − k) (the extra-sum-of-squares F test with an
// estimated dispersion); when φ = 0 with χ²_k as above. ΔBIC = −Δχ² + k·ln n with the floor in
// the variance.
//
// Thread-safety: pure function.
#include <Eigen/Dense>
#include <vector>

namespace demcal::diagnose {

struct Evidence {
  double delta_chi2 = 0;  // χ²_base − χ²_effect
  double lr_p_value = 1;
  double delta_bic = 0;
  bool significant = false;  // lr_p_value < significance and delta_bic < 0
  double floor = 0;          // the discrepancy floor estimated with the effect, single-run scatters
  // Standard deviation of the effect fit's floored χ² due to its own simulation noise (0 when the
  // fit was not simulated): Chi2NoiseSd below.
  double chi2_noise_sd = 0;
  // With the floor (EvidenceWithFloor): the effect fit's standardised residuals, the single-run
  // scatters q and the BIC penalty k·ln n, so that two candidates can be compared under one
  // common floor (ToldApart); empty without.
  Eigen::VectorXd residuals, q;
  double penalty = 0;
};

Evidence EvidenceOf(double chi2_base, double chi2_effect, int k, int n, double significance);
// r_base, r_effect: standardised residuals of the base and the effect's fit (fixed σ); q: the
// single-run scatter over σ per observation; fitted: the base's fitted coordinates p.
Evidence EvidenceWithFloor(const Eigen::VectorXd& r_base, const Eigen::VectorXd& r_effect,
                           const Eigen::VectorXd& q, int k, int fitted, double significance);

// One effect is named over another only on "strong" evidence, ΔBIC ≥ 6 (Kass & Raftery 1995:
// 0-2 "not worth more than a bare mention", 2-6 "positive", 6-10 "strong"): a wrong effect
// named with confidence is the failure to avoid, and "positive" evidence did name one (the
// elongated twin: rolling resistance 4.5 ahead of the true shape, both fits within noise).
constexpr double kBicIndistinct = 6.0;

// A simulated refit's χ² is itself a random variable: each simulated mean m_i carries a standard
// error s_i, and χ² = Σ r_i² w_i (r_i = (m_i − y_i)/σ_i, w_i = 1/(1 + φ² q_i²) the floor's
// weight) moves with it. To first order (the delta method), δχ² = Σ 2 r_i w_i δm_i/σ_i, so with
// independent means Var(χ²) ≈ Σ 4 r_i² w_i² u_i², u_i = s_i/σ_i. Rows that read one simulated
// mean (one source, Prediction::source) carry one error δm, which moves their terms together:
// they add before squaring, Var(χ²) ≈ Σ_sources (Σ_{i∈source} 2 r_i w_i u_i)². Counted as
// independent they would give up to √(rows per source) too little where their residuals share a
// sign, as they do on a fit that misses in one direction. The refit that ran its points where
// the noise happened to fall its way has the lower χ² by chance; the two ΔBIC of two candidates
// share the base fit, so their difference carries the two refits' noise, and its variance is
// the sum of the two.
//   u: s_i/σ_i per observation; q, phi as in discrepancy_floor.h; source: per observation its
//   simulated quantity (Sources(observations)); −1 or empty: its own.
double Chi2NoiseSd(const Eigen::VectorXd& r, const Eigen::VectorXd& u, const Eigen::VectorXd& q,
                   double phi, const std::vector<int>& source = {});
// The same with the rows' errors correlated: Var(χ²) ≈ aᵀ C a, a_i = 2 r_i w_i u_i, C the
// correlation of the rows' simulation errors (ErrorCorrelation). Rows of one run that read
// different observables (the angle and the height of one heap) move together as far as the run's
// replicates say they do (replicate_pool.h); the sources alone count them as independent, which
// overstates the noise where their terms have opposite signs and understates it where alike.
double CorrelatedChi2NoiseSd(const Eigen::VectorXd& r, const Eigen::VectorXd& u,
                             const Eigen::VectorXd& q, double phi,
                             const Eigen::MatrixXd& correlation);
// The n × n error correlation of rows: a row's own correlation row where all n rows carry one of
// length n (Prediction::correlation); otherwise 1 on the diagonal and within a source (≥ 0), 0
// elsewhere, which gives CorrelatedChi2NoiseSd the value of Chi2NoiseSd(..., source).
Eigen::MatrixXd ErrorCorrelation(const std::vector<int>& source,
                                 const std::vector<std::vector<double>>& rows, Eigen::Index n);

// The gap between two candidates' BIC. Each ΔBIC is taken with the floor estimated from that
// candidate's own fit, so each is measured against a differently floored base χ², and two
// values on different variance models are not comparable (the elongated twin: rolling 25 ahead
// of shape by ΔBIC, 3.2 apart when both fits are judged alike). When both carry their residuals
// the gap is (χ²_a + k_a ln n) − (χ²_b + k_b ln n), both χ² under the smaller of the two floors
// (the base's χ² then cancels). The smaller floor is the discrepancy the better of the two fits
// leaves unexplained: the data need no more than that, and a candidate that needs a larger floor
// is worse by that very fact. The larger floor would let a poor fit's own misfit absorb the gap
// it is judged by. Without residuals, the ΔBIC difference.
double BicGap(const Evidence& a, const Evidence& b);

// Two candidates are told apart only when their BIC gap (BicGap) is at least kBicIndistinct AND
// at least kNoiseSds standard deviations of the difference due to the refits' simulation noise
// (√(sd_a² + sd_b²), Chi2NoiseSd). The first is the statistics' "strong" evidence for
// deterministic fits; the second says the gap is not the luck of the simulated points (two
// standard deviations: a one-sided chance of about 2 % that the noise alone makes the gap). Used
// for the runner-up and for the control guard alike.
constexpr double kNoiseSds = 2.0;
double IndistinctWithin(const Evidence& a, const Evidence& b);
bool ToldApart(const Evidence& a, const Evidence& b);

}  // namespace demcal::diagnose
