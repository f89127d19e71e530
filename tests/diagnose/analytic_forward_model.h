#pragma once
// An analytic stand-in for the DEM behind `demcal diagnose` (no simulation): three observables
// (an "angle", a "height", a "flow") at three coating levels, a base model linear in one fitted
// parameter (a friction mu = 0.2 + 0.8·u on the unit cube), and candidate effects with
// distinct, known signatures — adhesion grows with the coating level, the others act in every
// condition, and the control moves exactly like the fitted parameter. Simulation noise is a
// fixed offset per observation (common random numbers: the same for every point), measurement
// noise a seeded Gaussian draw. Used by the loop, ranking and gap tests.
#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "calibrate/analytic_models.h"
#include "diagnose/gap/observation.h"
#include "diagnose/loop/forward_model.h"

namespace demcal::diagnose::testing {

inline const std::vector<double> kCoating = {0, 1.5, 3};
inline const std::vector<std::string> kKinds = {"angle_deg", "heap_height_m", "mass_flow_kg_s"};
inline const std::vector<double> kUncertainty = {1.0, 3e-4, 1e-4};  // measurement, per kind
inline const std::vector<double> kScatter = {1.0, 2e-4, 1e-4};      // single simulation run

// Change of observable `kind` at coating w for effect `e` with value v (per kind: angle, height,
// flow).
inline double EffectChange(int e, int kind, double w, double v) {
  switch (e) {
    case 0:
      return v * w * std::vector<double>{40, 2e-3, -2e-4}[kind];  // adhesion, per unit coating
    case 1:
      return v * std::vector<double>{30, 4e-3, -1e-4}[kind];  // rolling resistance
    case 2:
      return v * std::vector<double>{10, 6e-3, -5e-4}[kind];  // shape
    case 3:
      return v * std::vector<double>{-5, -3e-3, 2e-4}[kind];  // polydispersity
    case 4:
      return v * std::vector<double>{10, 1e-3, -1e-3}[kind];  // control: like mu
    case 5:
      return v * std::vector<double>{29, 3.9e-3, -1.1e-4}[kind];  // roughness: nearly rolling's
    case 6:  // decoy: shape's signature plus a little adhesion's, saturating at its probe 0.1
      return std::min(v, 0.1) *
             (std::vector<double>{10, 6e-3, -5e-4}[kind] + 0.02 * w * std::vector<double>{40, 2e-3, -2e-4}[kind]);
    case 7:  // slip: an added mechanism that moves everything nearly as less rolling does
      return v * std::vector<double>{-29, -3.9e-3, 1.1e-4}[kind];
  }
  return 0;
}

// Rolling is signed (the base assumes some rolling resistance, 0.3, that may be too much).
inline std::vector<CandidateEffect> Candidates() {
  return {{"adhesion", "", {{"g", "", 0, 0.2, 0.05}}},
          {"rolling",
           "",
           {{"t", "", -0.3, 1, 0.2, "more rolling resistance than assumed",
             "less rolling resistance than assumed"}}},
          {"shape", "", {{"t", "", 0, 2, 0.5}}},
          {"polydispersity", "", {{"t", "", 0, 1.5, 0.5}}},
          {"control", "", {{"t", "", -0.5, 0.5, 0.2}}, true, 0}};  // copies mu (coordinate 0)
}

// The library plus "roughness", whose signature is within a few per cent of rolling's: the
// two cannot be told apart on these observables.
inline std::vector<CandidateEffect> AmbiguousCandidates() {
  std::vector<CandidateEffect> c = Candidates();
  c.push_back({"roughness", "", {{"t", "", 0, 1, 0.2, "more roughness", ""}}});
  return c;
}

// The ambiguous library with rolling declared as re-valuing the base's assumed 0.3, the decoy
// (index 6), and "slip" (index 7), an added mechanism (assumed 0) whose signature is within a
// few per cent of less rolling resistance: the two cannot be told apart on these observables.
inline std::vector<CandidateEffect> SlipCandidates() {
  std::vector<CandidateEffect> c = AmbiguousCandidates();
  c[1].parameters[0].assumed = 0.3;
  c.push_back({"decoy", "", {{"t", "", 0, 2, 0.1}}});
  c.push_back({"slip", "", {{"t", "", 0, 1, 0.2, "more slip", ""}}});
  return c;
}

class AnalyticForwardModel final : public ForwardModel {
 public:
  int replicates = 3;
  uint64_t seed = 11;
  // Observation i: kind i % 3 at coating kCoating[i / 3].
  static int Kind(int i) { return i % 3; }
  static double Coating(int i) { return kCoating[i / 3]; }
  static int Count() { return 9; }

  // Noise-free value with mu and the effects (candidate index -> value). `curvature` c makes
  // every effect nonlinear, acting as v + c·v² (0: linear).
  // `angle_saturation` s > 0: the angle stops rising with mu above s (a heap whose grains roll
  // rather than slide), the other observables still respond.
  // `rolling_angle_above` scales rolling's change of the angle for values above 0 (0: the angle
  // no longer rises with more rolling resistance than the base's, yet falls with less).
  static double Exact(int i, double mu, const std::vector<std::pair<int, double>>& effects,
                      double curvature = 0, double angle_saturation = 0,
                      double rolling_angle_above = 1) {
    const int k = Kind(i);
    const double mu_k = k == 0 && angle_saturation > 0 ? std::min(mu, angle_saturation) : mu;
    double y =
        std::vector<double>{20, 0.012, 4e-3}[k] + mu_k * std::vector<double>{50, 5e-3, -5e-3}[k];
    for (const auto& [e, v] : effects)
      y += (e == 1 && k == 0 && v > 0 ? rolling_angle_above : 1) *
           EffectChange(e, k, Coating(i), v + curvature * v * v);
    return y;
  }
  double curvature = 0;
  double angle_saturation = 0;
  double rolling_angle_above = 1;
  bool shared_scenes = false;
  // An effect no candidate has: grows with the square of the coating, only in the flow.
  static double Foreign(int i, double v) {
    return Kind(i) == 2 ? v * Coating(i) * Coating(i) * 1e-4 : 0;
  }

  int BaseParameters() const override { return 1; }
  int SimulationsRun() const override { return runs_; }

  std::vector<Prediction> Evaluate(const std::vector<ModelPoint>& points) override {
    std::vector<Prediction> out;
    for (const ModelPoint& p : points) {
      std::vector<std::pair<int, double>> effects;
      for (const ActiveEffect& a : p.effects) effects.push_back({a.candidate, a.values[0]});
      Prediction pr{true, "ok"};
      for (int i = 0; i < Count(); ++i) {
        const double s = kScatter[Kind(i)];
        // shared_scenes: one simulated heap per kind read by every coating row (the noise draw
        // of the kind, not of the row), as a DEM base whose coating changes nothing runs once.
        pr.mean.push_back(
            Exact(i, 0.2 + 0.8 * p.base_unit[0], effects, curvature, angle_saturation,
                  rolling_angle_above) +
            s / std::sqrt(replicates) *
                calibrate::testing::Normal(seed, shared_scenes ? Kind(i) : i));
        pr.sem.push_back(s / std::sqrt(replicates));
        pr.spread.push_back(s);
        pr.source.push_back(shared_scenes ? Kind(i) : i);
      }
      runs_ += replicates;
      out.push_back(pr);
    }
    return out;
  }

  // Least squares over u on a fine grid (the model is linear: exact enough), J by central
  // difference.
  // base_stop_unit >= 0: the base calibration ends there instead (a calibration stopped on its
  // budget), its J a difference over base_step (negative: backwards), as a coarse optimiser's.
  // settle_at_scale: the calibration ends on its budget (at u = 1, unsettled) below this budget
  // scale, and settles from it on. blind_base: the base sensitivities come back zero (the data
  // cannot determine the base parameter).
  double base_stop_unit = -1, base_step = 0.01;
  int settle_at_scale = 1;
  double stall_shift = 0;  // > 0: unsettled rounds all stop at 1 − stall_shift (stagnation)
  // > 0 (with stall_shift): a noise-dominated objective. An unsettled round at budget scale b
  // returns the best (least-squares) of stall_draws·b packings at its stop point, each with its
  // own noise draw; the draws of a round include the earlier rounds' (a journal read back), so
  // twice the budget finds a lower χ² by the luck of more draws alone.
  int stall_draws = 0;
  bool blind_base = false;
  // > 0: each base sensitivity is reported with a standard error this multiple of its size (a
  // sensitivity estimated from noisy runs that does not resolve it).
  double sensitivity_noise = 0;
  std::vector<int> base_scales;  // the budget scales CalibrateBase was called with
  BaseCalibration CalibrateBase(int budget_scale) override {
    base_scales.push_back(budget_scale);
    const bool settles = budget_scale >= settle_at_scale;
    // Unsettled rounds stop nearer the truth each time (as a search given more budget does).
    const double stop = settles           ? base_stop_unit
                        : stall_shift > 0 ? 1.0 - stall_shift
                                          : 1.0 - 0.1 * std::log2(budget_scale);
    double best_u = stop, best = INFINITY;
    for (int g = 0; stop < 0 && g <= 1000; ++g) {
      const double u = g / 1000.0;
      const double chi2 = LeastSquares(Evaluate({{{u}, {}}})[0]);
      if (chi2 < best) best = chi2, best_u = u;
    }
    BaseCalibration b{true, "grid", {best_u}};
    b.prediction = Evaluate({{{best_u}, {}}})[0];
    for (int k = 0; !settles && k < stall_draws * budget_scale; ++k) {
      const uint64_t common = seed;
      seed = common + 1000 + k;  // another packing at the same point
      const Prediction p = Evaluate({{{best_u}, {}}})[0];
      seed = common;
      if (k == 0 || LeastSquares(p) < LeastSquares(b.prediction)) b.prediction = p;
    }
    const Prediction up = Evaluate({{{best_u + base_step}, {}}})[0];
    for (int i = 0; i < Count(); ++i) {
      b.jacobian.push_back({blind_base ? 0.0 : (up.mean[i] - b.prediction.mean[i]) / base_step});
      if (sensitivity_noise > 0) b.jacobian_sigma.push_back({sensitivity_noise * std::fabs(b.jacobian[i][0])});
    }
    b.termination = settles ? "converged" : "budget";
    b.settled = settles;
    b.max_evaluations = 10 * budget_scale;
    return b;
  }

  double LeastSquares(const Prediction& p) const {
    double chi2 = 0;
    for (int i = 0; i < Count(); ++i)
      chi2 += std::pow((p.mean[i] - measured[i]) / kUncertainty[Kind(i)], 2);
    return chi2;
  }

  std::vector<double> measured;  // set by MakeObservations
  int runs_ = 0;
};

// Measurements of the truth (mu plus hidden effects, plus `foreign` of the unknown effect) with
// seeded Gaussian noise of the stated uncertainties. offset_scatters > 0 adds a model-form
// offset: per observation a fixed shift of offset_scatters single-run scatters times a standard
// normal drawn once per dataset (another engine's differences: no pattern an effect has).
inline std::vector<Observation> MakeObservations(AnalyticForwardModel* model, double mu,
                                                 const std::vector<std::pair<int, double>>& hidden,
                                                 uint64_t noise_seed, double foreign = 0,
                                                 double offset_scatters = 0) {
  std::vector<Observation> obs;
  model->measured.clear();
  for (int i = 0; i < AnalyticForwardModel::Count(); ++i) {
    const int k = AnalyticForwardModel::Kind(i);
    const double y =
        AnalyticForwardModel::Exact(i, mu, hidden, model->curvature, model->angle_saturation,
                                    model->rolling_angle_above) +
        AnalyticForwardModel::Foreign(i, foreign) +
        offset_scatters * kScatter[k] * calibrate::testing::Normal(noise_seed + 7919, i) +
        kUncertainty[k] * calibrate::testing::Normal(noise_seed, i);
    model->measured.push_back(y);
    Observation o{kKinds[k] + " w=" + std::to_string(AnalyticForwardModel::Coating(i)),
                  kKinds[k],
                  {{"coating_wt_pct", std::to_string(AnalyticForwardModel::Coating(i))}},
                  y,
                  kUncertainty[k]};
    obs.push_back(o);
  }
  return obs;
}

}  // namespace demcal::diagnose::testing
