#pragma once
// Carried: which observables carried a ranking's choice — per observable, Σ over its rows of
// r_runner_up² − r_winner² (positive: it favours the winner) and of r_base² − r_winner² (what
// the winner fixed there), sorted by the first, largest first (diagnosis.json
// `steps[].observables_carried`).
//
//   std::vector<ObservableShare> s = Carried(r_base, observations, r_winner, &r_runner_up);
//
// Thread-safety: pure function.
#include <Eigen/Dense>
#include <string>
#include <vector>

#include "diagnose/gap/observation.h"

namespace demcal::diagnose {

struct ObservableShare {
  std::string observable;
  double against_runner_up = 0;
  double against_base = 0;
};

// r_base, winner, runner_up: standardised residuals per observation (runner_up may be null).
std::vector<ObservableShare> Carried(const Eigen::VectorXd& r_base,
                                     const std::vector<Observation>& observations,
                                     const Eigen::VectorXd& winner,
                                     const Eigen::VectorXd* runner_up);

}  // namespace demcal::diagnose
