// Particle factories: rate control, mixture mass fractions, determinism, bad input.
#include <catch2/catch.hpp>

#include <cmath>

#include "core/simulation/simulation.h"

using namespace demcal::core;

namespace {

// Two species (d = 2 mm, ρ 1000 and d = 3 mm, ρ 2500) poured from a box region into a bin.
Scene PourScene(double rate_kg_s) {
  Scene s;
  s.materials = {{"light", 5e6, 0.25, 1000}, {"heavy", 5e6, 0.25, 2500}};
  s.species = {{"a", 0, {}}, {"b", 1, {}}};
  s.species[0].size.diameter_m = 0.002;
  s.species[1].size.diameter_m = 0.003;
  s.pair_parameters.assign(4, PairParameters{});
  s.walls = BoxInnerFaces("bin", {0, 0, 0}, {0.06, 0.06, 0.3}, 0, true);
  s.domain_min_m = {0, 0, 0};
  s.domain_max_m = {0.06, 0.06, 0.3};
  FactorySpec f;
  f.name = "feed";
  f.region = InsertionRegion::Box({0.005, 0.005, 0.2}, {0.055, 0.055, 0.24});
  f.species = {0, 1};
  f.mass_fractions = {0.3, 0.7};
  f.mass_rate_kg_s = rate_kg_s;
  f.velocity_m_s = {0, 0, -0.5};
  s.factories = {f};
  s.seed = 7;
  return s;
}

}  // namespace

TEST_CASE("a factory delivers its mass rate and mixture", "[unit][factory]") {
  Simulation sim(PourScene(0.02), {.threads = 1});
  std::string err;
  REQUIRE(sim.Initialize(&err));
  REQUIRE(sim.Run(0.4).ok());
  const FactoryReport r = sim.FactoryReports().at(0);
  // Requested mass = rate × active time; achieved within one particle's mass per batch.
  CHECK(r.RequestedRate() == Approx(0.02).epsilon(1e-9));
  CHECK(r.AchievedRate() == Approx(0.02).epsilon(0.02));
  CHECK(r.full_batches == 0);
  double mass_a = 0, mass_total = 0;
  const Particles& p = sim.particles();
  for (size_t i = 0; i < p.Size(); ++i) {
    mass_total += p.mass_kg[i];
    if (p.species[i] == 0) mass_a += p.mass_kg[i];
  }
  CHECK(mass_total == Approx(r.inserted_mass_kg).epsilon(1e-12));
  // Mass fraction of species a: 0.3 up to multinomial sampling noise (a few hundred particles).
  const double n_particles = static_cast<double>(p.Size());
  CHECK(std::abs(mass_a / mass_total - 0.3) < 4 * std::sqrt(0.3 * 0.7 / n_particles) + 0.01);
}

TEST_CASE("factory insertion is deterministic from the seed", "[unit][factory]") {
  auto final_positions = [](uint64_t seed) {
    Scene s = PourScene(0.02);
    s.seed = seed;
    Simulation sim(s, {.threads = 1});
    std::string err;
    REQUIRE(sim.Initialize(&err));
    REQUIRE(sim.Run(0.05).ok());
    return sim.particles().position_m;
  };
  CHECK(final_positions(3) == final_positions(3));
  CHECK_FALSE(final_positions(3) == final_positions(4));
}

TEST_CASE("a factory region too small for its rate is a validation error", "[unit][factory]") {
  Scene s = PourScene(50.0);  // 50 kg/s through a 100 cm³ region
  std::string err;
  CHECK_FALSE(s.IsValid(&err));
  CHECK_THAT(err, Catch::Contains("factories[0].region") && Catch::Contains("too small"));
  s = PourScene(0.02);
  s.factories[0].mass_fractions = {0.5, 0.6};
  CHECK_FALSE(s.IsValid(&err));
  CHECK_THAT(err, Catch::Contains("sum to 1"));
}
