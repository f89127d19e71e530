// Near-spherical clumps run at the default time step (core/bodies/contact_multiplicity.h,
// docs/physics.md §1.5). Rig 3 of the cross-engine datasets (a narrow, steep funnel of soft,
// rough grains) with its grains made 3-sphere chains of aspect 1.05, whose members nearly
// coincide: at the smallest member's Rayleigh step every run ended energy_blow_up or non_finite
// by t = 0.06 s (4 of 4 replicates of this 1 g fill); with the step the rule shortens, they empty
// the funnel.
#include <catch2/catch.hpp>
#include <sstream>

#include "core/io/scratch_dir.h"
#include "experiments/common/run_experiment.h"
#include "workflow/test_paths.h"
#include "workflow/tiny_scene.h"

using namespace demcal::workflow;
using demcal::testing::ReadJson;
using demcal::testing::RepoRoot;
using demcal::testing::ScratchDir;

TEST_CASE("near-spherical 3-sphere chains pour through rig 3's funnel without blowing up",
          "[physics][timestep]") {
  nlohmann::json doc = ReadJson((RepoRoot() / "examples/diagnose/discharge_bp_narrow.json").string());
  doc["species"][0]["clump"] = {{"ellipsoid", {{"semi_axes", {1.05, 1, 1}}, {"sphere_count", 3}}}};
  doc["discharge"]["feed"]["mass_kg"] = 0.001;
  ExperimentFile file;
  std::string error;
  REQUIRE(ParseExperimentJson(doc, "near_spherical_rig3.json", &file, &error));
  ScratchDir dir("near_spherical_clumps");
  ExperimentContext context = ExperimentContextFor(file, dir.str("out"), /*quick=*/true);
  context.replicates = 1;
  context.threads = 1;
  context.quiet = true;
  std::ostringstream log;
  const ExperimentResult r = RunExperimentFile(file, context, log);
  INFO(log.str());
  CHECK(r.status == ExperimentStatus::kOk);
  CHECK(r.replicates_ok == 1);
}
