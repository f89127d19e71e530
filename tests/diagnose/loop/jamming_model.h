#pragma once
// A linear stand-in for the DEM whose runs have no value in chosen ranges of the parameters, as
// a funnel that jams: the refit tests' model (refit_probe_test.cc, refit_failure_test.cc).
#include <cmath>
#include <string>
#include <vector>

#include "diagnose/loop/forward_model.h"

namespace demcal::diagnose {

// mean_i = measured_i + a_i (u − u*) + b_i (t − t*), with u the one base parameter and t the
// effect's: the data are fitted exactly at (u*, t*). A run whose effect value is above `jam_above`
// or below `jam_below`, or inside (jam_from, jam_to), or whose base value is outside
// [u_jam_below, u_jam_above], has no value, as a funnel that jams.
class JammingModel : public ForwardModel {
 public:
  std::vector<double> measured{10, 20, 30, 40}, a{1, 1, 1, 1}, b{1, -1, 2, 0};
  double u_true = 0.5, t_true = 0.1;
  double jam_above = INFINITY, jam_below = -INFINITY;
  double jam_from = INFINITY, jam_to = INFINITY;
  double u_jam_above = INFINITY, u_jam_below = -INFINITY;
  int BaseParameters() const override { return 1; }
  std::vector<std::string> BaseParameterNames() const override { return {"u"}; }
  BaseCalibration CalibrateBase(int) override { return {}; }
  int SimulationsRun() const override { return runs_; }
  std::vector<Prediction> Evaluate(const std::vector<ModelPoint>& points) override {
    std::vector<Prediction> out;
    for (const ModelPoint& p : points) {
      ++runs_;
      const double u = p.base_unit[0], t = p.effects.empty() ? 0 : p.effects.back().values[0];
      if (t > jam_above || t < jam_below || (t > jam_from && t < jam_to) || u > u_jam_above ||
          u < u_jam_below) {
        out.push_back({false, "jammed"});
        continue;
      }
      Prediction pr{true, "ok"};
      for (size_t i = 0; i < measured.size(); ++i) {
        pr.mean.push_back(measured[i] + a[i] * (u - u_true) + b[i] * (t - t_true));
        pr.sem.push_back(0.01);
        pr.spread.push_back(1.0);
      }
      out.push_back(pr);
    }
    return out;
  }

 private:
  int runs_ = 0;
};

}  // namespace demcal::diagnose
