// Sinks (core/insertion/sink.h) and walls removed at a time (Wall::remove_at_s): a silo whose plug is taken
// away discharges into a sink; every removed body is counted once with its species' mass, the
// run is not a failure, and restarts and thread counts give identical results.
#include <catch2/catch.hpp>

#include <cstdio>
#include <filesystem>
#include <numeric>
#include <string>

#include <unistd.h>

#include "core/simulation/simulation.h"

using namespace demcal::core;

namespace {

constexpr double kPlugRemovedS = 0.08;

// A 3 × 3 cm square silo (four plane walls) closed by a plug at z = 0 that is removed at
// kPlugRemovedS; 150 spheres (d 2 mm) and 40 two-sphere clumps filled above it; a sink plane
// 2 cm below the opening. The domain ends 1 cm below the sink.
Scene Silo() {
  Scene s;
  s.materials = {{"m", 5e6, 0.25, 1500}};
  s.species = {{"balls", 0, {}, {}}, {"pairs", 0, {}, {{{-0.5, 0, 0}, 0.6}, {{0.5, 0, 0}, 0.6}}}};
  s.species[0].size.diameter_m = 0.002;
  s.species[1].size.diameter_m = 0.0025;
  PairParameters pair;
  pair.sliding_friction = 0.3;
  pair.restitution = 0.4;
  s.pair_parameters = {pair};
  s.rolling.name = "epsd";
  for (const PlaneWall& face : BoxInnerFaces("silo", {0, 0, 0}, {0.03, 0.03, 0.1}, 0, true))
    if (face.normal.z == 0) s.walls.push_back(face);
  Wall plug(PlaneWall{"plug", {0, 0, 0}, {0, 0, 1}, 0, {}});
  plug.remove_at_s = kPlugRemovedS;
  s.walls.push_back(plug);
  s.domain_min_m = {-0.01, -0.01, -0.03};
  s.domain_max_m = {0.04, 0.04, 0.1};
  s.fills = {{0, {0.001, 0.001, 0.001}, {0.029, 0.029, 0.05}, 150},
             {1, {0.001, 0.001, 0.05}, {0.029, 0.029, 0.09}, 40}};
  s.sinks = {SinkSpec::Plane("below", {0, 0, -0.02}, {0, 0, -1})};
  s.seed = 5;
  return s;
}

// Mass per species of the bodies still in the simulation (fixed spheres included).
std::vector<double> MassPerSpecies(const Simulation& sim) {
  std::vector<double> m(sim.scene().species.size(), 0.0);
  const Particles& p = sim.particles();
  for (size_t i = 0; i < p.Size(); ++i)
    if (p.body[i] < 0) m[p.species[i]] += p.mass_kg[i];
  const Clumps& c = sim.system().clumps;
  for (size_t k = 0; k < c.Size(); ++k) m[c.species[k]] += c.mass_kg[k];
  return m;
}

std::string TempPath(const std::string& tag) {
  return (std::filesystem::temp_directory_path() /
          ("demcal_sink_" + tag + "_" + std::to_string(::getpid()) + ".bin"))
      .string();
}

}  // namespace

TEST_CASE("a silo discharges into a sink once its plug is removed", "[unit][sink]") {
  Simulation sim(Silo(), {.threads = 1});
  std::string err;
  REQUIRE(sim.Initialize(&err));
  const std::vector<double> initial = MassPerSpecies(sim);
  const size_t plug = sim.walls().size() - 1;

  RunSummary r = sim.Run(kPlugRemovedS - 0.004);
  REQUIRE(r.ok());
  CHECK(sim.SinkReports().size() == 2);  // "below" and the implicit "domain"
  CHECK(sim.SinkReports()[0].TotalParticles() == 0);
  CHECK(sim.WallLoads()[plug].force_N.z < 0);  // the plug carries the fill
  CHECK_FALSE(sim.walls()[plug].removed);

  r = sim.Run(0.3);
  INFO(r.BriefReport());
  REQUIRE(r.ok());
  CHECK(sim.walls()[plug].removed);
  CHECK(sim.WallLoads()[plug].force_N.z == 0);
  const SinkReport& below = sim.SinkReports()[0];
  CHECK(below.name == "below");
  CHECK(below.particles[0] > 100);  // most fall 2 cm below the opening within 0.3 s
  CHECK(below.particles[1] > 20);
  CHECK(below.last_removal_s > kPlugRemovedS);
  // Nothing lost or counted twice: removed + remaining = initial, per species.
  const std::vector<double> now = MassPerSpecies(sim);
  for (size_t k = 0; k < 2; ++k) {
    const double removed = below.mass_kg[k] + sim.SinkReports()[1].mass_kg[k];
    CHECK(removed + now[k] == Approx(initial[k]).epsilon(1e-12));
  }
  CHECK(sim.system().clumps.Size() + below.particles[1] + sim.SinkReports()[1].particles[1] == 40);
  // The clump bookkeeping stays consistent: members point back at their clump.
  const Clumps& c = sim.system().clumps;
  for (size_t k = 0; k < c.Size(); ++k)
    for (uint32_t m = c.member_start[k]; m < c.member_start[k + 1]; ++m)
      CHECK(sim.particles().body[c.member_slot[m]] == static_cast<int>(k));
}

TEST_CASE("with a sink, a particle leaving the domain is removed, not a failure", "[unit][sink]") {
  Scene s = Silo();
  s.fills.clear();
  s.walls.clear();
  s.particles = {{0, {0.015, 0.015, 0.05}, {0.5, 0, 1.0}, {}, 0}};  // flies out sideways
  Simulation sim(s, {.threads = 1});
  std::string err;
  REQUIRE(sim.Initialize(&err));
  const RunSummary r = sim.Run(0.2);
  INFO(r.BriefReport());
  CHECK(r.ok());
  CHECK(sim.particles().Size() == 0);
  CHECK(sim.SinkReports()[1].name == "domain");
  CHECK(sim.SinkReports()[1].particles[0] == 1);
}

TEST_CASE("a discharge into a sink restarts bit-identically, for any thread count",
          "[unit][sink][checkpoint]") {
  const std::string path = TempPath("restart");
  std::string err;
  Simulation reference(Silo(), {.threads = 2});
  REQUIRE(reference.Initialize(&err));
  REQUIRE(reference.Run(0.12).ok());
  REQUIRE(reference.SinkReports()[0].TotalParticles() > 0);  // mid-discharge
  REQUIRE(reference.SaveCheckpoint(path, &err));
  REQUIRE(reference.Run(0.08).ok());

  Simulation restarted(Silo(), {.threads = 1});
  REQUIRE(restarted.Initialize(&err));
  REQUIRE(restarted.LoadCheckpoint(path, &err));
  REQUIRE(restarted.Run(0.08).ok());
  std::remove(path.c_str());

  Simulation single(Silo(), {.threads = 1});
  REQUIRE(single.Initialize(&err));
  REQUIRE(single.Run(0.2).ok());

  for (const Simulation* other : {&restarted, &single}) {
    INFO((other == &restarted ? "restarted" : "uninterrupted, 1 thread"));
    REQUIRE(other->particles().Size() == reference.particles().Size());
    CHECK(other->particles().position_m == reference.particles().position_m);
    CHECK(other->particles().velocity_m_s == reference.particles().velocity_m_s);
    CHECK(other->SinkReports()[0].mass_kg == reference.SinkReports()[0].mass_kg);
    CHECK(other->SinkReports()[0].last_removal_s == reference.SinkReports()[0].last_removal_s);
  }
}

TEST_CASE("sinks are validated", "[unit][sink]") {
  Scene s = Silo();
  std::string err;
  s.sinks[0].normal = {0, 0, -2};
  CHECK_FALSE(s.IsValid(&err));
  CHECK_THAT(err, Catch::Contains("sinks[0].normal"));
  s.sinks = {SinkSpec::Box("domain", {0, 0, 0}, {1, 1, 1})};
  CHECK_FALSE(s.IsValid(&err));
  CHECK_THAT(err, Catch::Contains("sinks[0].name"));
  s.sinks = {SinkSpec::Box("bin", {0, 0, 0}, {1, -1, 1})};
  CHECK_FALSE(s.IsValid(&err));
  CHECK_THAT(err, Catch::Contains("sinks[0].max_m"));
  // Finite is not enough: a point a galaxy away is a unit mistake (limits::kCoordinate).
  s.sinks = {SinkSpec::Plane("below", {0, 0, -1e300}, {0, 0, -1})};
  CHECK_FALSE(s.IsValid(&err));
  CHECK_THAT(err, Catch::Contains("sinks[0].point_m[2]"));
  s.sinks = {SinkSpec::Box("bin", {0, 0, 0}, {1, 1, 1e12})};
  CHECK_FALSE(s.IsValid(&err));
  CHECK_THAT(err, Catch::Contains("sinks[0].max_m[2]"));
  s.sinks = {SinkSpec::Plane("below", {0, 0, -0.02}, {0, 0, -1})};
  CHECK(s.IsValid(&err));
}
