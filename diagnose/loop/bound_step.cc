#include "diagnose/loop/bound_step.h"

#include <sstream>

#include "diagnose/ranking/discrepancy_floor.h"

namespace demcal::diagnose {
namespace {

Eigen::VectorXd ToVector(const std::vector<double>& v) {
  return Eigen::Map<const Eigen::VectorXd>(v.data(), v.size());
}

// The base fit's own evidence against itself: its residuals, the floor they carry, no extra
// parameter, and its χ²'s simulation noise (evidence.h), so that BicGap and ToldApart can
// compare an effect's refit with the base at its bound.
Evidence BaseEvidence(const std::vector<Observation>& at, const Eigen::VectorXd& r, int fitted) {
  Evidence e;
  e.residuals = r;
  e.q = ScatterPerSigma(at);
  e.floor = EstimateFloor(r, e.q, static_cast<int>(at.size()) - fitted);
  Eigen::VectorXd u(at.size());
  for (size_t i = 0; i < at.size(); ++i) u(i) = at[i].sem / at[i].Sigma();
  e.chi2_noise_sd = CorrelatedChi2NoiseSd(
      r, u, e.q, e.floor, ErrorCorrelation(Sources(at), Correlations(at), u.size()));
  return e;
}

bool Inside(const RankingEntry& e, const std::vector<BaseBound>& bounds) {
  if (!e.simulated || e.base_unit.empty()) return false;
  for (const BaseBound& b : bounds) {
    // The optimisers and the refits clamp onto a bound exactly; 1e-9 absorbs the unit map only.
    const double u = e.base_unit[b.coordinate];
    if (b.lower ? u <= 1e-9 : u >= 1 - 1e-9) return false;
  }
  return true;
}

std::string Value(const RankingEntry& e, const CandidateEffect& c) {
  std::ostringstream s;
  s.precision(3);
  const EffectParameter& p = c.parameters[0];
  s << e.key << " (" << EffectDirection(p, e.values.empty() ? 0 : e.values[0]) << ", " << p.name
    << " = " << (e.values.empty() ? 0 : e.values[0]) << (p.unit.empty() ? "" : " " + p.unit) << ")";
  return s.str();
}

}  // namespace

BoundCheck CheckBound(const StepOutcome& step, const FitState& fit,
                      const std::vector<Observation>& observations,
                      const std::vector<CandidateEffect>& candidates,
                      const std::vector<BaseBound>& bounds, const std::vector<std::string>& names,
                      const DiagnoseOptions& options) {
  BoundCheck b;
  std::ostringstream p;
  for (size_t k = 0; k < bounds.size(); ++k)
    p << (k ? " and " : "") << names[bounds[k].coordinate] << " beyond its "
      << (bounds[k].lower ? "lower" : "upper") << " bound";
  b.parameters = p.str();
  // The step's entries (the controls' free refits among them), then the effects held inside.
  std::vector<RankingEntry> entries = step.step.entries;
  entries.insert(entries.end(), step.inside_entries.begin(), step.inside_entries.end());
  std::vector<std::vector<double>> residuals = step.step.refit_residuals,
                                   signatures = step.unit_signatures;
  residuals.insert(residuals.end(), step.inside_residuals.begin(), step.inside_residuals.end());
  signatures.insert(signatures.end(), step.inside_signatures.begin(), step.inside_signatures.end());
  const std::vector<Observation> at =
      WithPrediction(observations, fit.prediction, options.discrepancy_floor);
  const Eigen::VectorXd sigma = Sigmas(at);
  const Eigen::VectorXd r0 = StandardisedResiduals(observations, fit.prediction.mean, sigma);
  std::vector<bool> inside, copies;
  for (const RankingEntry& e : entries) {
    inside.push_back(Inside(e, bounds));
    bool c = false;
    for (const BaseBound& bb : bounds) c = c || candidates[e.candidate].copies == bb.coordinate;
    copies.push_back(c && candidates[e.candidate].control);
  }
  b.judgement = JudgeBound(entries, inside, copies, BaseEvidence(at, r0, fit.Fitted()));
  const BoundJudgement& j = b.judgement;
  std::ostringstream s;
  s.precision(3);
  const std::string alternative =
      j.alternative >= 0
          ? " (the control " +
                Value(entries[j.alternative], candidates[entries[j.alternative].candidate]) + ")"
          : " (the base at its bound)";
  if (j.effect < 0) {
    b.text = "no effect of the library lets the base parameter back inside its range (" +
             b.parameters + alternative + "); widen the study's range to see where the fit goes";
    return b;
  }
  const RankingEntry& e = entries[j.effect];
  b.effect_candidate = e.candidate;
  b.effect_value = e.values.empty() ? 0 : e.values[0];
  b.effect_base_unit = e.base_unit;
  b.effect_chi2_per_dof = e.chi2_per_dof;
  const std::string effect = Value(e, candidates[e.candidate]);
  if (j.verdict == BoundVerdict::kOutranked) {
    const RankingEntry& w = entries[j.outranked_by];
    s << Value(w, candidates[w.candidate]) << " fits better than both " << b.parameters
      << alternative << " and " << effect << " with the base parameter inside (BIC gap "
      << BicGap(w.evidence, e.evidence) << " against the latter, beyond the tie margin of each)"
      << "; the base parameter stays on its bound with it";
  } else if (j.verdict == BoundVerdict::kEffect) {
    s << effect << " fits better with the base parameter inside its range than " << b.parameters
      << alternative << " (BIC gap " << j.bic_gap << ", beyond " << j.within << ")";
  } else if (j.verdict == BoundVerdict::kBeyondRange) {
    s << "the data ask for " << b.parameters << alternative
      << ": every effect that lets it back inside fits worse (best " << effect << ", BIC gap +"
      << j.bic_gap << ", beyond " << j.within << "); widen the study's range";
  } else {
    s << b.parameters << alternative << " or " << effect << " fit about equally (BIC gap "
      << j.bic_gap << " under the common floor, within " << j.within << ")";
    // The step's best effect may fit better than both without outranking them beyond their
    // noise (JudgeBound): dropping it would hide the best fit the step found, so it is named as
    // a third explanation level with them.
    if (step.has_winner) {
      const RankingEntry& w = step.step.entries[step.step.ranking.winner];
      if (w.simulated && !w.control && w.evidence.significant && w.candidate != e.candidate &&
          w.chi2_per_dof < e.chi2_per_dof) {
        b.also_candidate = w.candidate;
        s << ", or " << Value(w, candidates[w.candidate]) << ", which fits better than both "
          << "(chi2/dof " << w.chi2_per_dof << " against " << e.chi2_per_dof
          << ") but not beyond their noise";
      }
    }
    // The two explanations' predictions; the bound parameter's own sensitivity stands for
    // "beyond its range" beside the effect's signature, the other fitted parameters as they are.
    const Eigen::MatrixXd Js = sigma.cwiseInverse().asDiagonal() * fit.jacobian;
    Eigen::MatrixXd others(Js.rows(), 0);
    for (Eigen::Index c = 0; c < Js.cols(); ++c) {
      bool bound = false;
      for (const BaseBound& bb : bounds) bound = bound || bb.coordinate == c;
      if (bound) continue;
      others.conservativeResize(Eigen::NoChange, others.cols() + 1);
      others.col(others.cols() - 1) = Js.col(c);
    }
    const Eigen::VectorXd rb = j.alternative >= 0 ? ToVector(residuals[j.alternative]) : r0;
    b.separating = FindSeparatingMeasurement(
        others, sigma.cwiseInverse().cwiseProduct(ToVector(signatures[j.effect])),
        Js.col(bounds[0].coordinate), ToVector(residuals[j.effect]), rb, sigma, observations, e.key,
        names[bounds[0].coordinate] + " beyond its range");
  }
  b.text = s.str();
  return b;
}

}  // namespace demcal::diagnose
