#include "diagnose/ranking/separating_measurement.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "calibrate/target_gain.h"

namespace demcal::diagnose {

SeparatingMeasurement FindSeparatingMeasurement(
    const Eigen::MatrixXd& Js, const Eigen::VectorXd& sa, const Eigen::VectorXd& sb,
    const Eigen::VectorXd& ra, const Eigen::VectorXd& rb, const Eigen::VectorXd& sigma,
    const std::vector<Observation>& observations, const std::string& name_a,
    const std::string& name_b) {
  SeparatingMeasurement m;
  const Eigen::Index n = sa.size(), p = Js.cols();
  if (n == 0 || static_cast<Eigen::Index>(observations.size()) != n) return m;
  Eigen::MatrixXd J(n, p + 2);
  J << Js, sa, sb;
  std::vector<std::string> names;
  for (Eigen::Index j = 0; j < p; ++j) names.push_back("base" + std::to_string(j));
  names.push_back(name_a);
  names.push_back(name_b);
  std::vector<calibrate::CandidateTarget> targets;
  for (Eigen::Index i = 0; i < n; ++i) {
    targets.push_back({observations[i].name, {}});
    for (Eigen::Index j = 0; j < p + 2; ++j) targets.back().sensitivity.push_back(J(i, j));
  }
  const std::vector<calibrate::TargetGain> gains =
      calibrate::RankCandidateTargets(J, targets, names, std::vector<double>(p + 2, 1.0));
  double best = INFINITY, largest_difference = 0;
  for (Eigen::Index i = 0; i < n && i < static_cast<Eigen::Index>(gains.size()); ++i) {
    largest_difference = std::max(largest_difference, std::fabs(ra(i) - rb(i)));
    const calibrate::TargetGain& g = gains[i];
    const double shrink = (std::isfinite(g.shrink[p]) ? g.shrink[p] : 1) *
                          (std::isfinite(g.shrink[p + 1]) ? g.shrink[p + 1] : 1);
    const double score = shrink - (g.lifts_valley ? 1 : 0);  // a target that lifts the valley first
    if (score < best) best = score, m.observation = static_cast<int>(i);
  }
  if (m.observation < 0) return m;
  const int i = m.observation;
  const Observation& o = observations[i];
  m.prediction_a = o.measured + ra(i) * sigma(i);
  m.prediction_b = o.measured + rb(i) * sigma(i);
  m.difference_sigma = std::fabs(ra(i) - rb(i));
  m.shrink_a = gains[i].shrink[p];
  m.shrink_b = gains[i].shrink[p + 1];
  m.lifts_valley = gains[i].lifts_valley;
  m.separates = largest_difference >= 1;
  std::ostringstream s;
  s.precision(3);
  s << "measure " << o.observable << " at " << calibrate::DescribeCondition(o.condition)
    << (o.experiment.empty() ? "" : " (" + o.experiment + ")") << " again or more precisely (now "
    << o.measured << " +- " << o.uncertainty << "): " << name_a << "'s refit predicts "
    << m.prediction_a << ", " << name_b << "'s " << m.prediction_b << " (" << m.difference_sigma
    << " sigma apart); one more such value would shrink the "
    << "sigma of their parameters to " << m.shrink_a << " and " << m.shrink_b << " of now";
  if (!m.separates)
    s << ". No observation of this study has their refits more than one sigma apart: a new "
         "observable, "
         "condition or experiment is needed to tell them apart";
  m.description = s.str();
  return m;
}

}  // namespace demcal::diagnose
