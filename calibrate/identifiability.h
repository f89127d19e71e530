#pragma once
// IdentifiabilityReport: what the targets cannot tell, from the standardised sensitivity matrix J
// at the optimum (rows: residuals / sqrt(1 + noise²); columns: unit-cube parameters): its
// singular values, condition number, and in words each parameter combination the targets leave
// undetermined (the μs–μr valley of a single repose angle), with the SI increments along it.
//
// "Undetermined": a right singular vector v_i whose singular value s_i ≤ kUndeterminedSingular
// = sqrt(12). Moving by δ along v_i changes the chi-square by (s_i·δ)², so the data's σ along v_i
// is 1/s_i (unit cube); a uniform spread over the bounds has σ = 1/sqrt(12). Below the threshold
// the measurements constrain that combination less than the declared bounds already do: it is
// the bounds, not the data, that fix it. The threshold follows from the unit cube and the
// standardisation alone (no tuning to examples). Exactly null directions (rank deficiency) have
// σ = +∞.
//
//   IdentifiabilityReport r = AnalyseIdentifiability(J, {"mu_s", "mu_r"}, SiPerUnit(space, u));
//   if (!r.Identifiable()) std::cerr << r.summary;
//   // "mu_r and mu_s trade off: +1.00 mu_r ~ -0.82 mu_s (per range) ..."
//
// Thread-safety: plain values and a pure function.
#include <Eigen/Dense>
#include <string>
#include <vector>

namespace demcal::calibrate {

inline constexpr double kUndeterminedSingular = 3.4641016151377544;  // sqrt(12)

struct UndeterminedDirection {
  std::vector<double> unit_direction;  // unit-length, largest component +; per unit cube
  std::vector<double> si_direction;    // the same move in SI (unit_direction · dθ/du)
  double singular_value = 0;
  double sigma_unit = 0;    // 1 / s_i along it (+∞ when s_i = 0)
  std::string description;  // in words, naming the parameters involved
};

struct IdentifiabilityReport {
  std::vector<std::string> names;
  std::vector<double> singular_values;  // one per parameter, descending (0-padded)
  double condition_number = 0;          // s_max / s_min, +∞ when s_min = 0
  std::vector<UndeterminedDirection> undetermined;
  std::string summary;  // one line per finding, "" before analysis
  bool Identifiable() const { return undetermined.empty() && !singular_values.empty(); }
};

// names and si_per_unit: one per column of J. Components with |v_k| < 0.1·max|v| are left out of
// the words (they barely take part in the trade-off); the vectors keep them. noise_floor
// (jacobian_svd.h): a singular value at or below it is not resolved above the noise of J's
// entries and counts as zero (the combination is undetermined, σ = +∞).
IdentifiabilityReport AnalyseIdentifiability(const Eigen::MatrixXd& jacobian,
                                             const std::vector<std::string>& names,
                                             const std::vector<double>& si_per_unit,
                                             double noise_floor = 0);

}  // namespace demcal::calibrate
