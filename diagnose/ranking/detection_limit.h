#pragma once
// The smallest effect a diagnosis would have named: its detection limit (docs/diagnose/ranking.md,
// "What the data could not see"). "No missing effect" is an honest answer only with its power:
// an effect too weak for the data to carry is missed by any test, and the user needs to know how
// weak "too weak" is here.
//
// In the linearised model of a fit (the standardised sensitivities J of its fitted parameters, an
// effect's standardised signature s per unit of its parameter), an effect of size t moves the
// data by t·s; the fitted parameters absorb the part of s in the span of J, and the candidate's
// likelihood-ratio test sees the rest, t·‖P⊥ s‖ (P⊥ the projection off the span of J). Its
// statistic is then a non-central χ²₁ with √λ = |t|·‖P⊥ s‖, so the test at level a rejects with
// probability ≈ Φ(√λ − c) (c its critical value, the opposite tail negligible). Hence at power P
//   |t| = (c + z_P) / ‖P⊥ s‖,   z_P the standard normal quantile at P (1.2816 at 0.9).
// c is the ranking's own: the likelihood-ratio test at the step's per-candidate level α/K, with
// F(1, n − p − 1) in place of χ²₁ when a discrepancy floor φ > 0 was estimated (evidence.h), and
// at least √(ln n) so that ΔBIC < 0 holds too. Rows are weighted by 1/√(1 + φ² q_i²), the floor's
// variance model (discrepancy_floor.h).
// What it is not: exact for a response that is not linear in the effect (a heap saturates with
// rolling resistance), nor a statement that an effect of that size would be *named* over a rival
// that mimics it (the tie rules come after significance). It is the smallest effect that passes
// the first gate, taken from the signature at the fit.
//
//   DetectionLimit d = SmallestDetectable(J, s, q, 0.0, 0.01 / 7);
//   d.magnitude;       // |t| detected with probability 0.9
//
// Thread-safety: pure function.
#include <Eigen/Dense>

namespace demcal::diagnose {

inline constexpr double kDetectionPower = 0.9;

struct DetectionLimit {
  double magnitude = 0;       // |t| at kDetectionPower (infinity: the fit absorbs the signature)
  double magnitude_half = 0;  // |t| detected with probability one half: the threshold itself
  double critical = 0;        // c, the test's threshold in standard deviations
  double projected_norm = 0;  // ‖P⊥ s‖ in standardised units per unit of the parameter
};

// J: n × p standardised sensitivities of the fitted parameters (p may be 0); s: the standardised
// signature per unit of the effect's parameter; q: single-run scatter per σ; phi: the floor in
// single-run scatters (0: none estimated); per_candidate: the level of the candidate's own test.
DetectionLimit SmallestDetectable(const Eigen::MatrixXd& J, const Eigen::VectorXd& s,
                                  const Eigen::VectorXd& q, double phi, double per_candidate,
                                  double power = kDetectionPower);

}  // namespace demcal::diagnose
