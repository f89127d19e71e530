#include "diagnose/loop/detection_limits.h"

#include <algorithm>

#include "diagnose/loop/refit_work.h"
#include "diagnose/ranking/discrepancy_floor.h"

namespace demcal::diagnose {

std::vector<EffectDetection> DetectionLimitsAtFit(
    const std::vector<Observation>& observations, const FitState& fit, const DiagnosisStep& step,
    const std::vector<std::vector<double>>& unit_signatures,
    const std::vector<CandidateEffect>& candidates, const DiagnoseOptions& options,
    const Diagnosis& d) {
  std::vector<EffectDetection> out;
  const refits::Frame f = refits::MakeFrame(observations, fit, options);
  const double phi = EstimateFloor(f.r0, f.q, f.n() - f.fitted);
  const double per_candidate = options.significance / std::max<size_t>(1, step.entries.size());
  for (size_t i = 0; i < step.entries.size() && i < unit_signatures.size(); ++i) {
    const int c = step.entries[i].candidate;
    const bool spoken = candidates[c].control || d.Named(c) || d.MechanismNamed(candidates, c) ||
                        d.Revalued(c) ||
                        std::find(d.not_told_apart.begin(), d.not_told_apart.end(), c) !=
                            d.not_told_apart.end();
    if (spoken || unit_signatures[i].size() != static_cast<size_t>(f.n())) continue;
    const Eigen::VectorXd s =
        f.sigma.cwiseInverse().cwiseProduct(refits::ToVector(unit_signatures[i]));
    const EffectParameter& p = candidates[c].parameters[0];
    out.push_back({c, SmallestDetectable(f.J, s, f.q, phi, per_candidate), p.lower, p.upper,
                   s.squaredNorm() > 0});
  }
  return out;
}

}  // namespace demcal::diagnose
