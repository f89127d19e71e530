// The normal-law registry (normal_model.h): the pair table chooses the law, each law answers for
// its own pair properties, options and break gap, and a JKR law with Γ = 0 is Hertz–Mindlin.
#include <catch2/catch.hpp>

#include <string>
#include <variant>
#include <vector>

#include "core/contact/normal_model.h"

using namespace demcal::core;

namespace {

PairParameters Pair(double gamma_J_m2) {
  PairParameters p;
  p.interfacial_energy_J_m2 = gamma_J_m2;
  return p;
}

}  // namespace

TEST_CASE("every normal law of the registry is listed by its name", "[unit][contact]") {
  CHECK(NormalModelNames() == std::vector<std::string>{"hertz_mindlin", "jkr", "sjkr"});
  CHECK(NormalModelName(NormalModel{}) == "hertz_mindlin");
  CHECK(NormalModelName(JkrNormal{}) == "jkr");
}

TEST_CASE("the pair table calls for JKR when any pair has interfacial energy", "[unit][contact]") {
  CHECK(std::holds_alternative<HertzMindlinNormal>(SelectNormalModel({})));
  CHECK(std::holds_alternative<HertzMindlinNormal>(SelectNormalModel({Pair(0), Pair(0)})));
  CHECK(std::holds_alternative<JkrNormal>(SelectNormalModel({Pair(0), Pair(0.01)})));
}

TEST_CASE("a normal law takes its options from the contact_model section", "[unit][contact]") {
  RollingModelSpec spec;
  NormalModel model;
  spec.jkr_rolling_load = "repulsive";
  REQUIRE(MakeNormalModel({Pair(0.05)}, spec, &model));
  REQUIRE(std::holds_alternative<JkrNormal>(model));
  CHECK(std::get<JkrNormal>(model).rolling_load == JkrRollingLoad::kRepulsive);

  spec.jkr_rolling_load = "sideways";  // an option JKR does not know is refused, model kept
  CHECK_FALSE(MakeNormalModel({Pair(0.05)}, spec, &model));
  CHECK(std::get<JkrNormal>(model).rolling_load == JkrRollingLoad::kRepulsive);
  // Hertz–Mindlin has no options: JKR's are not its concern.
  CHECK(MakeNormalModel({Pair(0)}, spec, &model));
  CHECK(std::holds_alternative<HertzMindlinNormal>(model));
}

TEST_CASE("each law derives its own pair constants and break gap", "[unit][contact]") {
  constexpr double kEStar = 5e7, kGamma = 0.05, kR = 1e-3;
  const ResolvedPair adhesive = MakeResolvedPair(kEStar, kEStar, -0.2, 0.5, 0.1, kGamma);
  const ResolvedPair plain = MakeResolvedPair(kEStar, kEStar, -0.2, 0.5, 0.1, 0);
  CHECK(adhesive.jkr_adhesion_length == JkrNormal::AdhesionLength(kEStar, kGamma));
  CHECK(plain.jkr_adhesion_length == 0);
  CHECK(HertzMindlinNormal::BreakGap(kR, adhesive) == 0);
  CHECK(JkrNormal::BreakGap(kR, adhesive) == JkrNormal::BreakGap(kR, kEStar, kGamma));
  CHECK(JkrNormal::BreakGap(kR, plain) == 0);
  const double gap = JkrNormal::BreakGap(kR, adhesive);
  CHECK(JkrNormal::Holds(0.5 * gap, kR, adhesive));
  CHECK_FALSE(JkrNormal::Holds(0.5 * gap, kR, plain));
  CHECK_FALSE(HertzMindlinNormal::Holds(0.5 * gap, kR, adhesive));
  CHECK(HertzMindlinNormal::AttractionEnergyBound(kR, adhesive, 12) == 0);
  CHECK(JkrNormal::AttractionEnergyBound(kR, plain, 12) == 0);
  CHECK(JkrNormal::AttractionEnergyBound(kR, adhesive, 12) > 0);
}

TEST_CASE("JKR's force on a pair without interfacial energy is Hertz-Mindlin's, bit for bit",
          "[unit][contact]") {
  const ResolvedPair plain = MakeResolvedPair(5e7, 4e7, -0.3, 0.5, 0.1, 0);
  ContactGeometry g{};
  g.normal = {0, 0, 1};
  g.overlap_m = 2e-6;
  g.effective_radius_m = 1e-3;
  g.effective_mass_kg = 1e-5;
  g.relative_velocity_m_s = {0.01, 0, -0.05};
  for (const JkrRollingLoad load : {JkrRollingLoad::kNet, JkrRollingLoad::kRepulsive}) {
    ContactHistory hj{}, hh{};
    const NormalForce j = JkrNormal{load}.Force(g, plain, hj);
    const NormalForce h = HertzMindlinNormal{}.Force(g, plain, hh);
    CHECK(j.total_N == h.total_N);
    CHECK(j.elastic_N == h.elastic_N);
    CHECK(j.friction_load_N == h.friction_load_N);
    CHECK(j.rolling_load_N == h.rolling_load_N);
    CHECK(j.damping_N_s_m == h.damping_N_s_m);
  }
}
