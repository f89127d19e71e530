#include "diagnose/loop/fit_state.h"

#include <algorithm>
#include <cmath>

namespace demcal::diagnose {

std::vector<double> FitState::Coordinates() const {
  std::vector<double> c = point.base_unit;
  for (const ActiveEffect& e : point.effects) c.insert(c.end(), e.values.begin(), e.values.end());
  return c;
}

ModelPoint FitState::Step(const Eigen::VectorXd& delta, const ActiveEffect* added) const {
  ModelPoint next = point;
  Eigen::Index j = 0;
  for (double& u : next.base_unit) u += delta(j++);
  for (ActiveEffect& e : next.effects)
    for (double& v : e.values) v += delta(j++);
  if (added) next.effects.push_back(*added);
  return next;
}

std::vector<Observation> WithPrediction(const std::vector<Observation>& observations,
                                        const Prediction& p, double floor_factor) {
  std::vector<Observation> out = observations;
  for (size_t i = 0; i < out.size() && i < p.mean.size(); ++i) {
    out[i].simulated = p.mean[i];
    out[i].sem = p.sem[i];
    // The packing noise of a mean over `repeats` packings (none stated: one packing).
    out[i].floor = floor_factor * p.spread[i] / std::sqrt(std::max(1, out[i].repeats));
    out[i].scatter = p.spread[i];
    out[i].source = i < p.source.size() ? p.source[i] : -1;
    out[i].correlation = i < p.correlation.size() ? p.correlation[i] : std::vector<double>{};
  }
  return out;
}

Eigen::VectorXd Sigmas(const std::vector<Observation>& observations) {
  Eigen::VectorXd s(observations.size());
  for (size_t i = 0; i < observations.size(); ++i) s(i) = observations[i].Sigma();
  return s;
}

Eigen::VectorXd ScatterPerSigma(const std::vector<Observation>& observations) {
  Eigen::VectorXd q(observations.size());
  for (size_t i = 0; i < observations.size(); ++i)
    q(i) = observations[i].scatter / observations[i].Sigma();
  return q;
}

Eigen::VectorXd StandardisedResiduals(const std::vector<Observation>& observations,
                                      const std::vector<double>& mean,
                                      const Eigen::VectorXd& sigma) {
  Eigen::VectorXd r(observations.size());
  for (size_t i = 0; i < observations.size(); ++i)
    r(i) = (mean[i] - observations[i].measured) / sigma(i);
  return r;
}

}  // namespace demcal::diagnose
