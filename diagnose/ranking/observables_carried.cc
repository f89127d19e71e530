#include "diagnose/ranking/observables_carried.h"

#include <algorithm>
#include <map>

namespace demcal::diagnose {

std::vector<ObservableShare> Carried(const Eigen::VectorXd& r_base,
                                     const std::vector<Observation>& observations,
                                     const Eigen::VectorXd& winner,
                                     const Eigen::VectorXd* runner_up) {
  std::map<std::string, ObservableShare> by;
  for (Eigen::Index i = 0; i < r_base.size(); ++i) {
    ObservableShare& s = by[observations[i].observable];
    s.observable = observations[i].observable;
    s.against_base += r_base(i) * r_base(i) - winner(i) * winner(i);
    if (runner_up) s.against_runner_up += (*runner_up)(i) * (*runner_up)(i)-winner(i) * winner(i);
  }
  std::vector<ObservableShare> out;
  for (const auto& [name, s] : by) out.push_back(s);
  std::sort(out.begin(), out.end(), [](const ObservableShare& a, const ObservableShare& b) {
    return a.against_runner_up > b.against_runner_up;
  });
  return out;
}

}  // namespace demcal::diagnose
