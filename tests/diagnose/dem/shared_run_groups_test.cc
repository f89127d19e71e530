// Run groups that build the same scene (a condition no parameter or effect reads) run once;
// groups a condition changes, or of another experiment, stay apart.
#include "diagnose/dem/shared_run_groups.h"

#include <catch2/catch.hpp>

namespace demcal::diagnose {
namespace {

struct NullProbe final : calibrate::ExperimentProbe {
  std::string Kind() const override { return "null"; }
  std::vector<std::string> Observables() const override { return {"angle_deg"}; }
  calibrate::ProbeOutcome Run(const core::Scene&, uint64_t) const override { return {}; }
};

core::Scene OneMaterial() {
  core::Scene s;
  s.materials = {{"BP", 2.5e8, 0.25, 780}};
  s.pair_parameters.assign(1, core::PairParameters{});
  return s;
}

calibrate::ParameterSpace Friction() {
  calibrate::ParameterSpace space;
  space.parameters.push_back(
      {"mu_s", calibrate::PairProperty::kSlidingFriction, 0, 0, 0.2, 1.0, 0.5});
  return space;
}

calibrate::RunGroup Group(const NullProbe& probe, const std::string& coating,
                          const calibrate::ParameterSpace& space) {
  return {"heap|coating=" + coating, &probe, OneMaterial(), space, {{"coating", coating}}, {}};
}

}  // namespace

TEST_CASE("groups whose condition does not enter the model share one run", "[unit]") {
  const NullProbe heap, funnel;
  const calibrate::ParameterSpace space = Friction();
  const std::vector<calibrate::RunGroup> groups = {
      Group(heap, "0", space), Group(heap, "1.5", space), Group(funnel, "0", space),
      Group(heap, "3", space)};
  const std::vector<calibrate::TargetBinding> bindings = {
      {0, "angle_deg"}, {1, "angle_deg"}, {2, "angle_deg"}, {3, "angle_deg"}};
  const MergedRunGroups m = MergeSharedRunGroups(groups, bindings, space);
  REQUIRE(m.groups.size() == 2);  // the heap once, the funnel once
  CHECK(m.merged == 2);
  CHECK(m.groups[0].key == "heap|coating=0");
  CHECK(m.groups[1].probe == &funnel);
  REQUIRE(m.bindings.size() == 4);
  CHECK(m.bindings[0].group == 0);
  CHECK(m.bindings[1].group == 0);
  CHECK(m.bindings[2].group == 1);
  CHECK(m.bindings[3].group == 0);
  // The three heap targets read one simulated angle: one source for the χ² noise.
  CHECK(BindingSources(m.bindings) == std::vector<int>{0, 0, 2, 0});
  CHECK(BindingSources(bindings) == std::vector<int>{0, 1, 2, 3});
}

TEST_CASE("groups a condition changes stay apart", "[unit]") {
  const NullProbe heap;
  calibrate::ParameterSpace space = Friction();
  // Γ applies only at 3 wt% (a `when` condition): the 3 wt% scene differs from the 0 wt% one.
  space.parameters.push_back({"gamma_3",
                              calibrate::PairProperty::kInterfacialEnergy,
                              0,
                              0,
                              0.01,
                              0.2,
                              0.05,
                              false,
                              {{"coating", "3"}}});
  const std::vector<calibrate::RunGroup> groups = {
      Group(heap, "0", space), Group(heap, "1.5", space), Group(heap, "3", space)};
  const MergedRunGroups m =
      MergeSharedRunGroups(groups, {{0, "angle_deg"}, {1, "angle_deg"}, {2, "angle_deg"}}, space);
  REQUIRE(m.groups.size() == 2);  // 0 and 1.5 wt% share a scene, 3 wt% has its own
  CHECK(m.bindings[1].group == 0);
  CHECK(m.bindings[2].group == 1);

  // An effect written per condition (the prepare step reads the coating) keeps every group.
  std::vector<calibrate::RunGroup> prepared = groups;
  for (calibrate::RunGroup& g : prepared) {
    const double w = std::stod(g.condition.at("coating"));
    g.prepare = [w](core::Scene* s) { s->pair_parameters[0].rolling_friction = 0.1 * w; };
  }
  CHECK(MergeSharedRunGroups(prepared, {{0, "angle_deg"}}, space).groups.size() == 3);
}

}  // namespace demcal::diagnose
