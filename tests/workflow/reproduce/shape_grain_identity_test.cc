// Stage 1's shape search calibrates the grain the later stages run: the scene of one replicate
// built the way the search builds it (the count's experiment copy chained at the start aspect
// ratio, re-chained to the candidate by calibrate::SetPairProperty, then the fidelity) must be
// the scene built from the calibrated copy the later stages read (the clump written as an
// ellipsoid at the kept aspect ratio, parsed by files/scene_json_materials.cc). Same seed, same
// fingerprint part by part: any difference (clump spheres, size, time step, insertion, seed)
// would mean the grain calibrated is not the grain run later. No DEM is run.
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "calibrate/pair_property.h"
#include "core/scene/scene_fingerprint.h"
#include "experiments/aor/aor_experiment.h"
#include "experiments/aor/aor_section.h"
#include "objectives/common/fidelity.h"
#include "objectives/common/replicates.h"
#include "workflow/reproduce/experiment_edit.h"
#include "workflow/test_paths.h"

namespace demcal::workflow {
namespace {

// The experiment copy of examples/aor_ep.json with Table 1's EP rolling friction and `count`
// spheres on the spheroid [aspect, 1, 1], as experiment_edit.h writes it.
ExperimentFile Copy(double aspect, int count) {
  nlohmann::ordered_json e;
  std::string error;
  REQUIRE(ReadExperimentJson((testing::RepoRoot() / "examples/aor_ep.json").string(), &e, &error));
  SetPairProperty(&e, "EP", "EP", "rolling_friction", 0.05);
  SetSpeciesClump(&e, "EP", {aspect, 1, 1}, count);
  ExperimentFile file;
  INFO(error);
  REQUIRE(ParseEditedExperiment(e, "copy.json", &file, &error));
  return file;
}

// The scene replicate 0 runs at quick fidelity, from `model` (the parameters already set).
core::Scene ReplicateScene(const ExperimentFile& file, core::Scene model) {
  objectives::ApplyFidelity(file.quick_fidelity, &model);
  objectives::AorSettings settings;
  std::string error;
  INFO(error);
  REQUIRE(ParseAorSection(file.section, file.source, model, &settings, &error));
  int64_t fixed = 0;
  return objectives::BuildAorScene(model, settings, objectives::ReplicateSeed(file.seed, 0),
                                   &fixed);
}

TEST_CASE("shape search: the re-chained grain is the grain of the calibrated copy",
          "[reproduce]") {
  // The search's bracket evaluates the lower bound exactly (1.25 in the aspect-ratio twin); an
  // interior point exercises the same chain.
  const double aspect = GENERATE(1.25, 1.7);
  const int count = GENERATE(2, 3);
  const ExperimentFile searched = Copy(2.0, count);  // the count's copy, at the start ratio
  core::Scene rechained = searched.model;
  const int ep = rechained.species[0].material;
  calibrate::SetPairProperty(calibrate::PairProperty::kAspectRatio, ep, ep, aspect, &rechained);
  const core::Scene a = ReplicateScene(searched, rechained);

  const ExperimentFile kept = Copy(aspect, count);  // the calibrated copy
  const core::Scene b = ReplicateScene(kept, kept.model);

  INFO("aspect ratio " << aspect << ", " << count << " spheres");
  REQUIRE(a.species.size() == b.species.size());
  REQUIRE(a.species[0].clump_shape.size() == static_cast<size_t>(count));
  for (size_t k = 0; k < a.species[0].clump_shape.size(); ++k) {
    const core::ShapeSphere &p = a.species[0].clump_shape[k], &q = b.species[0].clump_shape[k];
    CHECK(p.radius == q.radius);  // bit-identical: a chaotic heap amplifies one ulp
    CHECK(p.centre.x == q.centre.x);
    CHECK(p.centre.y == q.centre.y);
    CHECK(p.centre.z == q.centre.z);
  }
  CHECK(core::TimeStep(a) == core::TimeStep(b));
  const std::vector<core::FingerprintPart> fa = core::SceneFingerprint(a, core::TimeStep(a), 0);
  const std::vector<core::FingerprintPart> fb = core::SceneFingerprint(b, core::TimeStep(b), 0);
  REQUIRE(fa.size() == fb.size());
  for (size_t k = 0; k < fa.size(); ++k) {
    INFO("fingerprint part '" << fa[k].name << "'");
    CHECK(fa[k].digest == fb[k].digest);
  }
}

}  // namespace
}  // namespace demcal::workflow
