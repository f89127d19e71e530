// A re-centred refit's finite-difference probe without a value (a jammed run) is retaken one step
// on the other side of the point, and the derivative taken one-sided from it (refit_work.h,
// RecentredRefits); with no value on either side the coordinate is held for that step. A
// signature run without a value is retaken at minus the probe value (candidate_step.cc). On a
// linear model a one-sided difference is exact, so one Gauss–Newton step from the retaken
// derivatives lands on the least-squares point (the normal equations' solution).
#include <catch2/catch.hpp>
#include <cmath>

#include "calibrate/sensitivity_refinement.h"
#include "diagnose/loop/candidate_step.h"
#include "diagnose/loop/refit_work.h"
#include "tests/diagnose/loop/jamming_model.h"
#include "tests/diagnose/loop/one_parameter_fit.h"

namespace demcal::diagnose {
namespace {

struct Setup {
  JammingModel model;
  std::vector<Observation> obs;
  CandidateEffect effect{"effect", "a stand-in", {{"t", "", -1, 1, 0.5}}};
  FitState fit;
  refits::Frame frame;
  refits::Work work{0};
  double h = 0;  // the probes' step in the unit cube

  Setup() : obs(4) {
    // Uncertainty 0.1: the kept point's misfit is tens of χ² units, so its re-centred step
    // promises a fall beyond kRefitChi2Unit and is simulated (refit_work.h).
    for (size_t i = 0; i < obs.size(); ++i)
      obs[i].measured = model.measured[i], obs[i].uncertainty = 0.1;
    fit = OneParameterFit(model, 0.4, 4);
    frame = FrameWithoutFloor(obs, fit);
    work.simulated = true;
    work.best_point = fit.point;
    work.best_point.effects = {{0, {0.3}}};
    work.best_prediction = model.Evaluate({work.best_point})[0];
    work.best_chi2 =
        StandardisedResiduals(obs, work.best_prediction.mean, frame.sigma).squaredNorm();
    // A stale signature parallel to the base column: stepping on it cannot move t.
    work.signature = Eigen::VectorXd::Constant(4, 1.0);
    double noise_max = 0;
    for (int k = 0; k < frame.n(); ++k)
      noise_max = std::max(noise_max, work.best_prediction.sem[k] / frame.sigma(k));
    h = calibrate::FiniteDifferenceStep(noise_max);
  }
};

}  // namespace

TEST_CASE("a jammed forward probe is retaken on the other side of the refit point", "[unit]") {
  Setup s;
  // The forward probe of t (0.3 + 2h, the effect's range being 2) jams; the backward one does not.
  s.model.jam_above = 0.3 + s.h;
  const int runs = s.model.SimulationsRun();
  refits::RecentredRefits(s.model, s.frame, s.fit, {s.effect}, {&s.work});
  // Two probes, the retake, then the full Gauss–Newton step, which lowers χ² (no half step).
  CHECK(s.model.SimulationsRun() - runs == 4);
  CHECK(s.work.best_point.effects.back().values[0] == Approx(s.model.t_true).margin(1e-9));
  CHECK(s.work.best_point.base_unit[0] == Approx(s.model.u_true).margin(1e-9));
  CHECK(s.work.best_chi2 == Approx(0).margin(1e-12));
  for (int i = 0; i < 4; ++i) CHECK(s.work.signature(i) == Approx(s.model.b[i]));
  CHECK(s.work.retake_note.empty());
}

TEST_CASE("a coordinate with no probe value on either side is held for the step", "[unit]") {
  Setup s;
  s.model.jam_above = 0.3 + s.h;
  s.model.jam_below = 0.3 - s.h;
  refits::RecentredRefits(s.model, s.frame, s.fit, {s.effect}, {&s.work});
  // t stays; u alone goes to its least-squares value at t = 0.3: the mean of the residuals
  // b_i (t − t*) over a_i = 1 is (1 − 1 + 2 + 0)/4 × 0.2 = 0.1, so u = u* − 0.1.
  CHECK(s.work.best_point.effects.back().values[0] == Approx(0.3));
  CHECK(s.work.best_point.base_unit[0] == Approx(s.model.u_true - 0.1));
  CHECK(s.work.retake_note.find("held for a refit step, t") != std::string::npos);
  CHECK(s.work.retake_note.find("jammed; on the other side: jammed") != std::string::npos);
}

TEST_CASE("a jammed signature run is retaken on the other side of the fit", "[unit]") {
  Setup s;
  // The probe value 0.5 jams; −0.5 does not. The fit is at t = 0, u = 0.4.
  s.model.jam_above = 0.25;
  DiagnoseOptions options;
  options.discrepancy_floor = 0;
  options.dem_refits = 0;  // the signature alone
  const StepOutcome out =
      RunCandidateStep(s.model, s.obs, {s.effect}, {0}, s.fit, options, nullptr, {});
  REQUIRE(out.unit_signatures.size() == 1);
  for (int i = 0; i < 4; ++i) CHECK(out.unit_signatures[0][i] == Approx(s.model.b[i]));
  CHECK(out.step.entries[0].note.find("signature taken one-sided at -0.5") != std::string::npos);
  // The change at the probe value, linearised from the other side: b_i × 0.5.
  for (int i = 0; i < 4; ++i) CHECK(out.step.signatures[0][i] == Approx(0.5 * s.model.b[i]));
}

TEST_CASE("every coordinate held in a step is named in the note", "[unit]") {
  Setup s;
  s.model.jam_above = 0.3 + s.h;
  s.model.jam_below = 0.3 - s.h;
  const double u0 = s.fit.point.base_unit[0];
  s.model.u_jam_above = u0 + 0.5 * s.h;
  s.model.u_jam_below = u0 - 0.5 * s.h;
  refits::RecentredRefits(s.model, s.frame, s.fit, {s.effect}, {&s.work});
  // Nothing can move: the point stays, and both coordinates are said to be held.
  CHECK(s.work.best_point.effects.back().values[0] == Approx(0.3));
  CHECK(s.work.best_point.base_unit[0] == Approx(u0));
  CHECK(s.work.retake_note.find("held for a refit step, u") != std::string::npos);
  CHECK(s.work.retake_note.find("held for a refit step, t") != std::string::npos);
}

TEST_CASE("a re-centred refit point without a value is said in the note", "[unit]") {
  Setup s;
  // The Gauss–Newton step from t = 0.3 lands on the truth t = 0.1, which jams; its half, 0.2,
  // does not (the probes at 0.3 ± 2h are above 0.2).
  s.model.jam_from = 0.05;
  s.model.jam_to = 0.15;
  refits::RecentredRefits(s.model, s.frame, s.fit, {s.effect}, {&s.work});
  CHECK(s.work.best_point.effects.back().values[0] == Approx(0.2));
  CHECK(s.work.retake_note.find("re-centred refit point t = 0.1 had no value (jammed)") !=
        std::string::npos);
}

}  // namespace demcal::diagnose
