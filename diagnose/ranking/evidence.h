#pragma once
// Evidence for one candidate effect: how much better the augmented model (base + effect, refit)
// fits than the base model, in the two standard currencies.
//  - Likelihood ratio: with Gaussian standardised residuals, −2 ln Λ = χ²_base − χ²_effect, which
//    under "the effect is absent" follows a chi-square with k degrees of freedom (Wilks 1938; k
//    the effect's parameters). p < significance: the improvement is beyond what fitting k more
//    parameters to noise gives.
//  - ΔBIC = χ²_effect − χ²_base + k·ln(n) (Schwarz 1978, n observations): the penalty k·ln n is
//    the statistics', not ours. Negative favours the effect; Kass & Raftery (1995) read
//    |ΔBIC| < 2 as "not worth more than a bare mention", so two candidates closer than 2 are
//    not told apart.
//
//   Evidence e = EvidenceOf(chi2_base, chi2_effect, 1, 15, 0.01);
//
// Thread-safety: pure function.
namespace demcal::diagnose {

struct Evidence {
  double delta_chi2 = 0;  // χ²_base − χ²_effect
  double lr_p_value = 1;
  double delta_bic = 0;
  bool significant = false;  // lr_p_value < significance and delta_bic < 0
};

Evidence EvidenceOf(double chi2_base, double chi2_effect, int k, int n, double significance);

// Kass & Raftery's (1995) "not worth more than a bare mention": |ΔBIC| below this.
constexpr double kBicIndistinct = 2.0;

}  // namespace demcal::diagnose
