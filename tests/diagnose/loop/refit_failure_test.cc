// A simulated refit point without a value (a funnel that jams, a run that blows up) is no better
// than the fit: half the Gauss–Newton step is simulated in its place, and a candidate none of
// whose refit points has a value keeps its signature run as its simulated point and re-centres
// from there (refit_work.h, SimulateRefits), so the ranking judges it on a simulated fit rather
// than on a linearisation. The signature run is a probe of the refit like the finite-difference
// probes: when it fits better than every refit point it is the refit (KeepSignatureRun). The
// stand-in is linear, so every step lands where the normal equations say.
#include <catch2/catch.hpp>
#include <cmath>

#include "diagnose/loop/candidate_step.h"
#include "diagnose/loop/refit_work.h"
#include "tests/diagnose/loop/jamming_model.h"
#include "tests/diagnose/loop/one_parameter_fit.h"

namespace demcal::diagnose {
namespace {

// The base fit at u = 0.4 (the truth 0.5), the effect off (the truth t = 0.1); the effect's
// range [−1, 1], probe 0.5. One candidate, refitted by simulation: with σ = 0.01 the base misses
// by 10–30 σ, so its linearised refit is significant and shortlisted.
struct Step {
  JammingModel model;
  std::vector<Observation> obs;
  CandidateEffect effect{"effect", "a stand-in", {{"t", "", -1, 1, 0.5}}};
  FitState fit;
  DiagnoseOptions options;

  Step() : obs(4) {
    for (size_t i = 0; i < obs.size(); ++i)  // σ small enough for the gap to be significant
      obs[i].measured = model.measured[i], obs[i].uncertainty = 0.01;
    fit = OneParameterFit(model, 0.4, 4);
    options.discrepancy_floor = 0;
    options.dem_refits = 1;
    options.extra_refits = 0;
  }
  RankingEntry Run() {
    const StepOutcome out =
        RunCandidateStep(model, obs, {effect}, {0}, fit, options, nullptr, {});
    REQUIRE(out.step.entries.size() == 1);
    return out.step.entries[0];
  }
};

}  // namespace

TEST_CASE("a refit point without a value is retaken at half the step toward the fit", "[unit]") {
  Step s;
  s.model.jam_from = 0.07;  // the Gauss–Newton point t = 0.1 jams, the half step 0.05 does not
  s.model.jam_to = 0.2;
  const RankingEntry e = s.Run();
  REQUIRE(e.simulated);
  REQUIRE(e.values.size() == 1);
  CHECK(e.values[0] == Approx(0.05));
  CHECK(e.base_unit[0] == Approx(0.45));
  CHECK(e.note.find("refit point t = 0.1 had no value (jammed); at half the step: ok") !=
        std::string::npos);
}

TEST_CASE("a candidate whose refit points have no value is refitted from its signature run",
          "[unit]") {
  Step s;
  s.model.jam_from = 0;  // the refit points t = 0.1 and 0.05 jam; the signature run, 0.5, not
  s.model.jam_to = 0.25;
  SECTION("without re-centred points the signature run is the refit") {
    const RankingEntry e = s.Run();
    REQUIRE(e.simulated);
    CHECK(e.values[0] == Approx(0.5));
    CHECK(e.note.find("at half the step: jammed") != std::string::npos);
    CHECK(e.note.find("refitted from its signature run") != std::string::npos);
  }
  SECTION("a re-centred point steps from the signature run") {
    s.options.extra_refits = 1;
    const RankingEntry e = s.Run();
    // From (0.4, 0.5) the step to the truth (0.5, 0.1) jams; its half, (0.45, 0.3), does not.
    REQUIRE(e.simulated);
    CHECK(e.values[0] == Approx(0.3));
    CHECK(e.base_unit[0] == Approx(0.45));
  }
}

TEST_CASE("the signature run is the refit when it fits better than every refit point",
          "[unit]") {
  JammingModel model;
  std::vector<Observation> obs(4);
  for (size_t i = 0; i < obs.size(); ++i) obs[i].measured = model.measured[i];
  const FitState fit = OneParameterFit(model, 0.4, 4);
  const refits::Frame f = FrameWithoutFloor(obs, fit);
  const CandidateEffect effect{"effect", "a stand-in", {{"t", "", -1, 1, 0.5}}};
  refits::Work w{0};
  w.simulated = true;
  w.best_point = fit.point;
  w.best_point.effects = {{0, {0.3}}};
  w.best_prediction = model.Evaluate({w.best_point})[0];
  w.best_chi2 = StandardisedResiduals(obs, w.best_prediction.mean, f.sigma).squaredNorm();
  ModelPoint exact;
  exact.base_unit = {model.u_true};
  exact.effects = {{0, {model.t_true}}};
  SECTION("a signature run with a value") {
    refits::KeepSignatureRun(f, exact, model.Evaluate({exact})[0], &w);
    refits::RefineRefits(model, f, fit, {effect}, 0, {&w});
    CHECK(w.best_point.effects.back().values[0] == Approx(model.t_true));
    CHECK(w.best_chi2 == Approx(0).margin(1e-12));
  }
  SECTION("a signature run without a value is not a probe") {
    refits::KeepSignatureRun(f, exact, Prediction{false, "jammed"}, &w);
    refits::RefineRefits(model, f, fit, {effect}, 0, {&w});
    CHECK(w.best_point.effects.back().values[0] == Approx(0.3));
  }
}

}  // namespace demcal::diagnose
