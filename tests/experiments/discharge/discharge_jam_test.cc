// A jammed funnel is reported as a jam (status "jammed", a message saying how long nothing left
// and how much stayed), never as a slow flow with a discharge time; the calibration probe passes
// the jam on as the run's status with no values.
#include <catch2/catch.hpp>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "experiments/common/run_experiment.h"
#include "experiments/discharge/discharge_experiment.h"
#include "experiments/discharge/discharge_probe.h"
#include "experiments/discharge/discharge_test_scenes.h"
#include "core/io/scratch_dir.h"
#include "workflow/test_paths.h"

using namespace demcal;
using namespace demcal::objectives;

namespace {

// Rough glass-like beads of diameter d: high sliding and rolling friction (EPSD2), so that an
// arch over an orifice of about three grains, once formed, holds.
core::Scene RoughBeads(double d_m, double rolling_friction) {
  core::Scene model = test::GlassBeads(
      d_m, 2500,
      core::PairParameters{.sliding_friction = 0.8, .rolling_friction = rolling_friction,
                           .restitution = 0.3});
  model.rolling.name = "epsd2";
  return model;
}

// About 190 beads of 2 mm in a small funnel (top 12 d, a 4 d cylinder) that gives up soon.
DischargeSettings SmallFunnel(double d_m, double orifice_m) {
  DischargeSettings s = test::PlacedFunnel(d_m, orifice_m, 0.002);
  s.hopper.top_diameter_m = 12 * d_m;
  s.hopper.cylinder_height_m = 4 * d_m;
  s.catch_depth_m = 8 * d_m;
  s.settle.max_time_s = 2;
  s.stall_s = 0.3;
  s.max_discharge_s = 3;
  return s;
}

}  // namespace

// Zuriguel et al. 2005 (Phys. Rev. E 71:051303): in 3D the mean avalanche before an arch blocks
// an orifice of D/d ≈ 3 is a few grains (it grows exponentially with D/d, beyond 10⁴ grains
// above D/d ≈ 5), so a 3.1 d orifice jams long before 190 grains have passed; rolling friction
// makes the arches sturdier. The wide orifice (7 d, frictionless rolling) is the contrast: the
// same funnel empties, so a status that always said "jammed" would fail here.
TEST_CASE("discharge: a funnel blocked by an arch is reported jammed and never as a slow flow",
          "[physics]") {
  const double d = 0.002;
  const DischargeSettings narrow = SmallFunnel(d, 3.1 * d);
  std::string error;
  REQUIRE(narrow.IsValid(RoughBeads(d, 0.5), &error));
  for (uint64_t seed : {11u, 12u}) {
    const DischargeRun run = RunDischarge(RoughBeads(d, 0.5), narrow, seed, {});
    INFO("seed " << seed << ": " << run.status << ": " << run.message);
    CHECK(run.status == "jammed");
    CHECK_FALSE(run.ok());
    CHECK(run.message.find("no outflow for 0.3 s") != std::string::npos);
    CHECK(run.message.find("left in the hopper") != std::string::npos);
    CHECK(run.fill_mass_kg > 0);
    // Never a discharge time for a funnel that did not empty.
    CHECK_FALSE(run.metrics.ok);
    CHECK(run.metrics.discharge_time_s == 0);

    const calibrate::DischargeProbe probe(narrow);
    const calibrate::ProbeOutcome outcome = probe.Run(RoughBeads(d, 0.5), seed);
    CHECK(outcome.status == "jammed");
    CHECK(outcome.values.empty());
  }

  const DischargeSettings wide = SmallFunnel(d, 7 * d);
  const DischargeRun flowing = RunDischarge(RoughBeads(d, 0.0), wide, 11, {});
  INFO(flowing.status << ": " << flowing.message);
  CHECK(flowing.status == "ok");
  CHECK(flowing.ok());
  CHECK(flowing.metrics.discharge_time_s > 0);
}

// The same through the experiment's front door, on the diagnosis examples' funnel: rough grains
// (EPSD2 rolling friction 0.4, the LIGGGHTS setting that jammed this funnel) and an orifice of
// just over 3 grains. The console line names the jam, and no discharge time is reported.
TEST_CASE("discharge experiment: the console and the result name a jam", "[physics]") {
  std::ifstream in(demcal::testing::RepoRoot() / "examples/diagnose/discharge_bp_small.json");
  nlohmann::json scene = nlohmann::json::parse(in);
  scene["interactions"]["default"]["rolling_friction"] = 0.4;
  scene["contact_model"]["rolling"] = "epsd2";
  scene["discharge"]["hopper"]["orifice_diameter_m"] = 0.0076;  // 3.04 grains at quick fidelity
  demcal::testing::ScratchDir dir("discharge_jam");
  const std::string path = dir.str("jam.json");
  std::ofstream(path) << scene.dump();
  workflow::ExperimentFile file;
  std::string error;
  REQUIRE(workflow::LoadExperimentFile(path, &file, &error));
  workflow::ExperimentContext context = workflow::ExperimentContextFor(file, dir.str("out"), true);
  context.replicates = 1;
  context.quiet = true;
  std::ostringstream log;
  const workflow::ExperimentResult r = workflow::RunExperimentFile(file, context, log);
  INFO(log.str());
  CHECK(r.replicates_ok == 0);
  CHECK(r.status == workflow::ExperimentStatus::kRunFailed);
  CHECK(log.str().find("1 jammed (no outflow for 0.5 s with") != std::string::npos);
  REQUIRE(r.Value("discharge_time_s"));
  CHECK(r.Value("discharge_time_s")->n == 0);
}
