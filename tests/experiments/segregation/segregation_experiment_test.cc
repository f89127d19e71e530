// Segregation-heap experiment: scene building (box, funnel, feed), and a tiny DEM run whose heap
// analysis, angle, discharge clock and tracked granules are all defined.
#include "experiments/segregation/segregation_experiment.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <set>
#include <variant>

#include "core/simulation/simulation.h"

namespace demcal::objectives {
namespace {

// Three species of coarse spheres (a few hundred per gram) and a wall material, all pairs alike.
core::Scene CoarseTernaryModel() {
  core::Scene m;
  for (const auto& [name, density] :
       {std::pair{"BP", 780.0}, {"TAED", 850.0}, {"EP", 2320.0}, {"perspex", 1180.0}})
    m.materials.push_back({name, core::Material::YoungsFromShear(1e6, 0.25), 0.25, density});
  const double d[3] = {0.002, 0.0028, 0.0024};
  for (int k = 0; k < 3; ++k) {
    core::Species s;
    s.name = m.materials[k].name;
    s.material = k;
    s.size.kind = core::SizeDistribution::Kind::kFixed;
    s.size.diameter_m = d[k];
    m.species.push_back(s);
  }
  core::PairParameters pair;
  pair.sliding_friction = 0.6;
  pair.rolling_friction = 0.1;
  pair.restitution = 0.2;
  m.pair_parameters.assign(16, pair);
  m.rolling.name = "cdt";
  return m;
}

SegregationSettings TinySettings() {
  SegregationSettings s;
  s.feed.components = {{0, 0.8}, {1, 0.1}, {2, 0.1}};
  s.feed.mass_kg = 0.0012;
  s.feed.mass_rate_kg_s = 0.02;
  s.width_m = 0.07;
  s.depth_m = 0.012;
  s.pour_height_m = 0.04;
  s.feed_width_m = 0.016;
  s.funnel = {
      .enabled = true, .orifice_diameter_m = 0.014, .top_diameter_m = 0.03, .height_m = 0.015};
  s.wall_material = 3;
  s.settle.max_time_s = 1.5;
  s.settle.specific_kinetic_J_kg = 1e-4;
  s.tracking.granules = 4;
  s.tracking.start_fraction = 0.2;
  s.segregation.random.repetitions = 50;
  return s;
}

TEST_CASE("segregation scene: open box, funnel on the box axis, feed with the mass fractions",
          "[unit]") {
  const core::Scene model = CoarseTernaryModel();
  const SegregationSettings s = TinySettings();
  std::string error;
  REQUIRE(s.IsValid(model, &error));
  int64_t fixed = 0;
  const core::Scene scene = BuildSegregationScene(model, s, 7, &fixed);
  REQUIRE(scene.IsValid(&error));
  CHECK(fixed > 0);
  CHECK(static_cast<int64_t>(scene.particles.size()) == fixed);
  CHECK(scene.walls.size() == 6);  // 5 faces of an open-topped box + the funnel
  const auto* cone = std::get_if<core::ConeFrustumSurface>(&scene.walls.back().shape);
  REQUIRE(cone != nullptr);
  CHECK(cone->axis_point_m.x == Approx(0.035));
  CHECK(cone->axis_point_m.y == Approx(0.006));
  CHECK(cone->height0_m == Approx(0.04));
  CHECK(cone->radius0_m == Approx(0.007));
  CHECK(cone->radius1_m == Approx(0.015));
  REQUIRE(scene.factories.size() == 1);
  const core::FactorySpec& feed = scene.factories[0];
  CHECK(feed.species == std::vector<int>{0, 1, 2});
  CHECK(feed.mass_fractions == std::vector<double>{0.8, 0.1, 0.1});
  CHECK(feed.total_mass_kg == Approx(0.0012));
  CHECK(feed.region.min_m.z > 0.055);  // above the funnel top
  CHECK(s.TrackedSpecies() == 1);      // the first minor component

  SegregationSettings no_funnel = s;
  no_funnel.funnel.enabled = false;
  const core::Scene direct = BuildSegregationScene(model, no_funnel, 7, &fixed);
  CHECK(direct.walls.size() == 5);
  CHECK(direct.factories[0].region.min_m.z == Approx(0.04));
}

TEST_CASE("segregation scene with a clump feed: the glued base is a sphere layer", "[unit]") {
  core::Scene model = CoarseTernaryModel();
  model.species[0].clump_shape = {{{-0.5, 0, 0}, 0.6}, {{0.5, 0, 0}, 0.6}};  // the base's species
  const SegregationSettings s = TinySettings();
  std::string error;
  REQUIRE(s.IsValid(model, &error));
  int64_t fixed = 0;
  const core::Scene scene = BuildSegregationScene(model, s, 7, &fixed);
  INFO(error);
  CHECK(scene.IsValid(&error));  // fixed particles must be spheres
  REQUIRE(fixed > 0);
  REQUIRE(scene.species.size() == model.species.size() + 1);
  CHECK(scene.species.back().clump_shape.empty());
  CHECK(scene.species.back().material == model.species[0].material);
  CHECK(scene.particles.front().species == static_cast<int>(model.species.size()));
}

TEST_CASE("segregation settings name the offending field", "[unit]") {
  const core::Scene model = CoarseTernaryModel();
  std::string error;
  SegregationSettings s = TinySettings();
  s.funnel.orifice_diameter_m = 0.006;  // ≈ 2 largest diameters
  CHECK_FALSE(s.IsValid(model, &error));
  CHECK_THAT(error, Catch::Contains("segregation.funnel.orifice_diameter_m"));
  s = TinySettings();
  s.tracking.sample_interval_s = 0;
  CHECK_FALSE(s.IsValid(model, &error));
  CHECK_THAT(error, Catch::Contains("segregation.tracking.sample_interval_s"));
  s = TinySettings();
  s.settle.max_time_s = 0.01;
  CHECK_FALSE(s.IsValid(model, &error));
  CHECK_THAT(error, Catch::Contains("max_time_s"));
}

bool Finite(const SegregationIndex& i) {
  return std::isfinite(i.cov_m) && std::isfinite(i.cov_r) && std::isfinite(i.s_n);
}

TEST_CASE("a tiny segregation heap run gives a defined analysis", "[physics][slow]") {
  const core::Scene model = CoarseTernaryModel();
  const SegregationSettings s = TinySettings();
  const SegregationRun run = RunSegregation(model, s, 11, {});
  INFO(run.Status() << ": " << run.settle.message << run.analysis_message);
  REQUIRE(run.ok());
  CHECK(run.particles > 150);
  CHECK(run.spheres_left_above == 0);
  CHECK(run.discharge_time_s > 0);
  CHECK(run.first_out_s < run.empty_s);
  // Fig. 16's outflow: every heap grain passed the orifice once, so the outflow's composition
  // is the heap's (mass conservation), and each bin's fractions sum to 1 (or 0 if empty).
  REQUIRE(run.outflow_mass_fraction.size() == 3);
  std::vector<double> heap_kg(3, 0);
  double heap_total = 0;
  for (const auto& g : run.heap.grains) heap_kg[g.species] += g.mass_kg, heap_total += g.mass_kg;
  for (int k = 0; k < 3; ++k)
    CHECK(run.outflow_mass_fraction[k] == Approx(heap_kg[k] / heap_total).epsilon(1e-9));
  REQUIRE(run.outflow.size() == 20);
  for (const CompositionBin& bin : run.outflow) {
    double sum = 0;
    for (double f : bin.mass_fraction) sum += f;
    CHECK((sum == Approx(1.0) || (sum == 0 && bin.mass_kg == 0)));
  }
  REQUIRE(run.analysis.has_value());
  CHECK(run.analysis->grid.face_bin_count() == 21);
  CHECK(run.analysis->grid.layers() == 8);
  const HeapSegregation& h = run.analysis->indices;
  CHECK(h.layers.size() == 8);
  REQUIRE(h.whole.species.size() == 3);
  for (const RegionSegregation* region : {&h.front, &h.back, &h.whole})
    for (const SpeciesSegregation& sp : region->species)
      CHECK((Finite(sp.number) && Finite(sp.mass)));
  CHECK(h.whole.species[0].mass.defined);  // the major component fills many bins
  CHECK(h.whole.species[0].mass.mean_fraction > 0.5);
  CHECK(run.angle.ok);
  CHECK(run.angle.angle_deg > 10);
  CHECK(run.angle.angle_deg < 60);

  REQUIRE(!run.tracked.empty());
  std::set<int64_t> heap_ids;
  for (const Grain& g : run.heap.grains) heap_ids.insert(g.id);
  for (const TrackedGranule& g : run.tracked) {
    CHECK(heap_ids.count(g.track.id) == 1);
    CHECK(g.track.species == 1);
    CHECK(!g.track.samples.empty());
  }
}

}  // namespace
}  // namespace demcal::objectives
