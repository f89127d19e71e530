// A refit ends on the best simulated point of base + effect, its finite-difference probes
// included (refit_work.h, RefineRefits): the likelihood ratio compares maximised likelihoods,
// and a probe that fits better than every refit point is the better fit. A probe re-centres the
// refit points only when it fits better beyond the simulation noise of the difference; a
// re-centred step is simulated only where its fresh sensitivities promise a fall of χ².
#include "diagnose/loop/refit_work.h"

#include <catch2/catch.hpp>
#include <cmath>

#include "calibrate/sensitivity_refinement.h"
#include "tests/diagnose/loop/jamming_model.h"
#include "tests/diagnose/loop/one_parameter_fit.h"

namespace demcal::diagnose {
namespace {

// A forward model whose simulated means are "packings" that depend on where they are run: every
// point misses the measurements by ±`miss`, except the points whose effect value is `lucky`,
// which miss them by a quarter of that. A stand-in for a noisy DEM objective where the
// Gauss–Newton steps land on unlucky packings and one probe on a lucky one (the secant through
// the probe extrapolates past it: the step lands elsewhere).
class PacketModel : public ForwardModel {
 public:
  std::vector<double> measured;
  double lucky = 0, miss = 3;
  double lucky_miss = 0.25;  // the lucky points' miss, as a fraction of `miss`
  int BaseParameters() const override { return 1; }
  BaseCalibration CalibrateBase(int) override { return {}; }
  int SimulationsRun() const override { return runs_; }
  std::vector<Prediction> Evaluate(const std::vector<ModelPoint>& points) override {
    std::vector<Prediction> out;
    for (const ModelPoint& p : points) {
      const double m = !p.effects.empty() && std::fabs(p.effects.back().values[0] - lucky) < 1e-12
                           ? miss * lucky_miss
                           : miss;
      Prediction pr{true, "ok"};
      for (size_t i = 0; i < measured.size(); ++i) {
        // Alternating signs: no step of the one base parameter and the effect removes it.
        pr.mean.push_back(measured[i] + (i % 2 ? -m : m));
        pr.sem.push_back(0.5);
        pr.spread.push_back(1.0);
      }
      ++runs_;
      out.push_back(pr);
    }
    return out;
  }

 private:
  int runs_ = 0;
};

// The PacketModel scene: four observations, the effect t in [-1, 1], one base parameter at 0.5.
struct Packets {
  PacketModel model;
  std::vector<Observation> obs;
  CandidateEffect effect{"effect", "a stand-in", {{"t", "", -1, 1, 0.5}}};
  FitState fit;
  refits::Frame frame;
  Packets() : obs(4) {
    model.measured = {10, 20, 30, 40};
    for (size_t i = 0; i < obs.size(); ++i) obs[i].measured = model.measured[i];
    fit = OneParameterFit(model, 0.5, 4);
    frame = FrameWithoutFloor(obs, fit);
  }
};

// A refit kept at the simulated point fit + the effect at `value`.
refits::Work SimulatedAt(PacketModel& model, const FitState& fit, double value) {
  refits::Work w{0};
  w.simulated = true;
  w.best_point = fit.point;
  w.best_point.effects = {{0, {value}}};
  w.best_prediction = model.Evaluate({w.best_point})[0];
  return w;
}

}  // namespace

TEST_CASE("a refit ends on a finite-difference probe that fits better", "[unit]") {
  PacketModel model;
  model.measured = {10, 20, 30, 40};
  std::vector<Observation> obs(4);
  for (size_t i = 0; i < obs.size(); ++i) obs[i].measured = model.measured[i];
  CandidateEffect effect{"effect", "a stand-in", {{"t", "", -1, 1, 0.5}}};
  const FitState fit = OneParameterFit(model, 0.5, 4);
  const refits::Frame f = FrameWithoutFloor(obs, fit);
  refits::Work w = SimulatedAt(model, fit, 0.2);
  w.best_chi2 = 4 * 3.0 * 3.0 / (1 + 0.25);  // σ² = u² + sem² = 1.25
  w.signature = Eigen::VectorXd::Constant(4, 1.0);
  // The effect's probe is one finite-difference step of its range (2) above the kept point: the
  // calibration layer's step for the noise there (sem/σ = 0.5/√1.25).
  const double h = calibrate::FiniteDifferenceStep(0.5 / std::sqrt(1.25));
  model.lucky = 0.2 + h * 2;
  const int runs = model.SimulationsRun();
  refits::RefineRefits(model, f, fit, {effect}, 4, {&w});
  // One round: two probes, the step and its half; the steps did not lower χ², so the points end
  // (the probe's gain is not the points' progress).
  REQUIRE(model.SimulationsRun() - runs == 4);
  CHECK(w.best_chi2 == Approx(4 * 0.75 * 0.75 / 1.25));
  CHECK(w.best_point.effects.back().values[0] == Approx(model.lucky));
  CHECK(w.best_point.base_unit[0] == Approx(0.5));
}

TEST_CASE("a simulated refit's chi2 noise adds the rows that read one simulated mean", "[unit]") {
  // The stand-in misses ±3 in turn (σ² = 1 + 0.5², u = 0.5/√1.25 on every row): four terms
  // 2·r·w·u of one size and alternating sign. Rows of one source (one simulated scene read by
  // two table rows) share its error: same-sign pairs add to √2 times the independent sd,
  // opposite-sign pairs cancel. Counted as independent rows, all three would be equal.
  PacketModel model;
  model.measured = {10, 20, 30, 40};
  std::vector<Observation> obs(4);
  for (size_t i = 0; i < obs.size(); ++i) obs[i].measured = model.measured[i];
  const std::vector<CandidateEffect> effect = {{"effect", "a stand-in", {{"t", "", -1, 1, 0.5}}}};
  const FitState fit = OneParameterFit(model, 0.5, 4);
  const refits::Frame f = FrameWithoutFloor(obs, fit);
  refits::Work w = SimulatedAt(model, fit, 0.2);
  w.signature = Eigen::VectorXd::Constant(4, 1.0);
  w.refit = refits::Refit(f, effect[0].parameters[0], w.signature);
  const Eigen::VectorXd r = StandardisedResiduals(obs, w.best_prediction.mean, f.sigma);
  w.best_chi2 = r.squaredNorm();
  auto noise = [&](std::vector<int> source) {
    w.best_prediction.source = std::move(source);
    RankingEntry e;
    refits::Fill(f, w, effect, r, &e);
    return e.evidence.chi2_noise_sd;
  };
  const double own = noise({});
  REQUIRE(own > 0);
  CHECK(noise({0, 1, 2, 3}) == Approx(own));
  CHECK(noise({0, 1, 0, 1}) == Approx(std::sqrt(2.0) * own));
  CHECK(noise({0, 0, 1, 1}) == Approx(0).margin(1e-12));
}

}  // namespace demcal::diagnose

namespace demcal::diagnose {
namespace {

// A refit at 0.2 whose signature run (a probe, kept aside) sits at the lucky value 0.6.
refits::Work WithLuckyProbe(Packets& s) {
  refits::Work w = SimulatedAt(s.model, s.fit, 0.2);
  w.best_chi2 = StandardisedResiduals(s.obs, w.best_prediction.mean, s.frame.sigma).squaredNorm();
  w.signature = Eigen::VectorXd::Constant(4, 1.0);
  s.model.lucky = 0.6;
  w.probe_point = s.fit.point;
  w.probe_point.effects = {{0, {0.6}}};
  w.probe_prediction = s.model.Evaluate({w.probe_point})[0];
  w.probe_chi2 = StandardisedResiduals(s.obs, w.probe_prediction.mean, s.frame.sigma).squaredNorm();
  return w;
}

}  // namespace

TEST_CASE("a probe better beyond the noise re-centres the refit points", "[unit]") {
  // Misses of 3 and 0.75 (σ² = 1.25): χ² 28.8 against 1.8, 27 apart; the sd of the difference
  // is √(4.8² + 1.2²) = 4.9 (2·r·u per row, u = 0.5/√1.25, four independent rows), so the gap is
  // 5.5 sd, beyond the ranking's 2 (evidence.h, kNoiseSds).
  Packets s;
  refits::Work w = WithLuckyProbe(s);
  REQUIRE(w.best_chi2 == Approx(28.8));
  REQUIRE(w.probe_chi2 == Approx(1.8));
  std::vector<std::string> lines;
  refits::RefineRefits(s.model, s.frame, s.fit, {s.effect}, 4, {&w},
                       [&lines](const std::string& line) { lines.push_back(line); });
  CHECK(w.retake_note.find("re-centred on a probe with chi2 1.8 against 28.8") !=
        std::string::npos);
  CHECK(w.best_chi2 == Approx(1.8));
  // One round from the probe, which no step improves on: the progress line says so.
  CHECK(lines ==
        std::vector<std::string>{"re-centred refit round 1: effect chi2 1.8 -> 1.8 (settled)"});
  CHECK(w.best_point.effects.back().values[0] == Approx(0.6));
}

TEST_CASE("a probe better only by its noise does not re-centre the refit points", "[unit]") {
  // Lucky misses of 0.9 × 3: χ² 28.8 against 23.3, 5.5 apart, within 2 sd (4.8 and 4.3).
  Packets s;
  s.model.lucky_miss = 0.9;
  refits::Work w = WithLuckyProbe(s);
  REQUIRE(w.best_chi2 - w.probe_chi2 == Approx(28.8 * (1 - 0.81)));
  const int runs = s.model.SimulationsRun();
  refits::RefineRefits(s.model, s.frame, s.fit, {s.effect}, 4, {&w});
  CHECK(w.retake_note.find("re-centred") == std::string::npos);
  // Two probes around the refit at 0.2 (not around the probe at 0.6), and no step: no move of
  // the base and the effect removes misses of alternating sign, so the step promises no fall.
  CHECK(s.model.SimulationsRun() - runs == 2);
  // When the points end, the better probe is the refit all the same (the header's rule).
  CHECK(w.best_point.effects.back().values[0] == Approx(0.6));
}

TEST_CASE("a re-centred step that promises no fall of chi2 is not simulated", "[unit]") {
  // The linear stand-in, its refit kept where it fits the data exactly: the two finite-difference
  // probes are run, the Gauss–Newton step from them promises nothing, and nothing more runs.
  JammingModel model;
  std::vector<Observation> obs(4);
  for (size_t i = 0; i < obs.size(); ++i) obs[i].measured = model.measured[i];
  const CandidateEffect effect{"effect", "a stand-in", {{"t", "", -1, 1, 0.5}}};
  const FitState fit = OneParameterFit(model, 0.4, 4);
  const refits::Frame f = FrameWithoutFloor(obs, fit);
  refits::Work w{0};
  w.simulated = true;
  w.best_point = fit.point;
  w.best_point.base_unit = {model.u_true};
  w.best_point.effects = {{0, {model.t_true}}};
  w.best_prediction = model.Evaluate({w.best_point})[0];
  w.best_chi2 = 0;
  w.signature = Eigen::VectorXd::Constant(4, 1.0);
  const int runs = model.SimulationsRun();
  refits::RecentredRefits(model, f, fit, {effect}, {&w});
  CHECK(model.SimulationsRun() - runs == 2);
  CHECK(w.best_point.effects.back().values[0] == Approx(model.t_true));
  CHECK(w.best_point.base_unit[0] == Approx(model.u_true));
}

}  // namespace demcal::diagnose
