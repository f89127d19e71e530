#include "workflow/export/liggghts_deck.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>

#include "experiments/common/experiment_file.h"
#include "tests/workflow/test_paths.h"
#include "workflow/export/liggghts_dump.h"
#include "workflow/export/liggghts_insertion.h"
#include "workflow/export/liggghts_number.h"
#include "workflow/export/liggghts_walls.h"

using namespace demcal;
using namespace demcal::workflow;

namespace {

ExperimentFile AorBp() {
  ExperimentFile file;
  std::string error;
  REQUIRE(
      LoadExperimentFile((testing::RepoRoot() / "examples/aor_bp.json").string(), &file, &error));
  return file;
}

struct Exported {
  bool ok = false;
  std::string deck, error;
  std::vector<std::pair<std::string, std::string>> files;
  nlohmann::ordered_json summary;
  ExportRun run;
};

Exported Export(const ExperimentFile& file, const ExportOptions& options) {
  Exported e;
  e.ok = ExportRunOf(file, file.quick_fidelity, &e.run, &e.error) &&
         LiggghtsDeck(e.run, options, {"test"}, &e.deck, &e.files, &e.summary, &e.error);
  return e;
}

ExportOptions TorqueConversion() {
  ExportOptions o;
  o.law.cdt_torque_conversion = true;
  return o;
}

// The commands LIGGGHTS-PUBLIC 3.8 knows that an exported deck may use.
const std::set<std::string> kCommands = {
    "units",     "atom_style",   "atom_modify", "boundary",      "newton",       "communicate",
    "read_data", "region",       "create_box",  "neighbor",      "neigh_modify", "soft_particles",
    "fix",       "pair_style",   "pair_coeff",  "timestep",      "group",        "compute",
    "variable",  "thermo_style", "thermo",      "thermo_modify", "dump",         "run",
    "label",     "if",           "next",        "jump",          "write_dump",   "print",
    "unfix"};

}  // namespace

TEST_CASE("export: the aor deck has every part, each line a LIGGGHTS command", "[unit][export]") {
  const ExperimentFile file = AorBp();
  const Exported e = Export(file, TorqueConversion());
  REQUIRE(e.ok);
  std::istringstream lines(e.deck);
  std::string line;
  while (std::getline(lines, line)) {
    if (line.empty() || line[0] == '#') continue;
    const std::string word = line.substr(0, line.find(' '));
    INFO(line);
    CHECK(kCommands.count(word) == 1);
  }
  const std::string& d = e.deck;
  CHECK_THAT(
      d, Catch::Contains("pair_style gran model hertz tangential history rolling_friction cdt\n"));
  // G = 1e8 Pa, ν 0.25 at stiffness ×0.01: E = 2G(1 + ν) × 0.01 = 2.5e6 Pa.
  CHECK_THAT(d, Catch::Contains("youngsModulus peratomtype 2500000 2.5e+07\n"));
  CHECK_THAT(d, Catch::Contains("coefficientRollingFriction peratomtypepair 2 0.2 0.055 0.055 "));
  CHECK_THAT(d, Catch::Contains("read_data particles.data\n"));
  CHECK_THAT(d, Catch::Contains("neigh_modify exclude group fixed fixed\n"));
  CHECK_THAT(d, Catch::Contains("primitive type 2 zplane 0\n"));
  CHECK_THAT(d, Catch::Contains("primitive type 2 xplane 0.06\n"));
  CHECK_THAT(d, Catch::Contains("mass 0.0025 massrate 0.0185 insert_every "));
  CHECK_THAT(d, Catch::Contains("fix integrate flow nve/sphere\n"));
  CHECK_THAT(d, Catch::Contains("write_dump all custom post/final.liggghts"));
  // A sieve cut of 425–500 µm at size ×5: five equal-number classes, radii 1.08125–1.23125 mm.
  CHECK_THAT(d, Catch::Contains("particletemplate/sphere") &&
                    Catch::Contains("radius constant 0.00108125\n") &&
                    Catch::Contains("radius constant 0.00123125\n"));
  CHECK_THAT(d, Catch::Contains("t1_1 0.2 t1_2 0.2 t1_3 0.2 t1_4 0.2 t1_5 0.2\n"));
  // Δt as demcal takes it: the fraction of the Rayleigh time.
  const double dt = e.summary["timestep_s"].get<double>();
  CHECK(dt == Approx(e.run.scene.time.rayleigh_fraction * core::RayleighTime(e.run.scene)));
  CHECK_THAT(d, Catch::Contains("timestep " + Num(dt) + "\n"));
  // E 2.5 MPa is below LIGGGHTS' default SI floor (5 MPa), Perspex's 25 MPa within it.
  CHECK_THAT(d, Catch::Contains("soft_particles yes\n") && !Catch::Contains("hard_particles"));
  REQUIRE(e.files.size() == 1);
  CHECK(e.files[0].first == "particles.data");
  CHECK(e.summary["fixed_particles"].get<int64_t>() ==
        static_cast<int64_t>(e.run.scene.particles.size()));
}

TEST_CASE("export: cdt without the torque option and JKR are refused, naming the pair",
          "[unit][export]") {
  ExperimentFile file = AorBp();
  Exported e = Export(file, {});
  CHECK_FALSE(e.ok);
  CHECK_THAT(e.error, Catch::Contains("material pair BP–BP") && Catch::Contains("cdt"));
  file.model.rolling.name = "epsd2";
  file.model.pair_parameters[0].interfacial_energy_J_m2 = 0.05;
  e = Export(file, {});
  CHECK_FALSE(e.ok);
  CHECK_THAT(e.error, Catch::Contains("material pair BP–BP") && Catch::Contains("JKR"));
  ExportOptions sjkr;
  sjkr.law.sjkr_approximation = true;
  e = Export(file, sjkr);
  REQUIRE(e.ok);
  CHECK_THAT(e.deck, Catch::Contains("cohesion sjkr rolling_friction epsd2"));
  CHECK_THAT(e.deck, Catch::Contains("cohesionEnergyDensity"));
}

TEST_CASE("export: the discharge deck fills, opens the gate, runs until the hopper is empty",
          "[unit][export]") {
  ExperimentFile file;
  std::string error;
  REQUIRE(LoadExperimentFile((testing::RepoRoot() / "examples/discharge_bp.json").string(), &file,
                             &error));
  const Exported e = Export(file, TorqueConversion());
  REQUIRE(e.ok);
  // The funnel's cone and cylinder as STL meshes behind one wall fix; the gate a primitive.
  REQUIRE(e.files.size() >= 2);
  CHECK_THAT(e.deck, Catch::Contains("mesh/surface file meshes/wall1_hopper_cone.stl"));
  CHECK_THAT(e.deck, Catch::Contains("fix meshes all wall/gran ") &&
                         Catch::Contains(" mesh n_meshes 2 meshes w1_mesh w2_mesh\n"));
  const size_t settled = e.deck.find("label settle_done\n");
  const size_t open = e.deck.find("unfix w3\n");
  REQUIRE(settled != std::string::npos);
  REQUIRE(open != std::string::npos);
  CHECK(settled < open);
  CHECK_THAT(e.deck, Catch::Contains("if \"${left} == 0\" then \"jump SELF discharge_done\""));
  CHECK(e.summary["opening"]["wall"] == "gate");
  // Segregation is not exported, and says why.
  file.experiment = "segregation";
  ExportRun run;
  CHECK_FALSE(ExportRunOf(file, file.quick_fidelity, &run, &error));
  CHECK_THAT(error, Catch::Contains("'segregation' is not exported"));
}

TEST_CASE("export: walls as primitives or STL meshes; moving walls refused", "[unit][export]") {
  core::Scene s;
  s.materials = {{"steel", 2e9, 0.3, 7800}};
  s.walls.push_back(core::Wall(
      "silo", 0, core::CylinderSurface{.axis_point_m = {0.1, 0.2, 0}, .radius_m = 0.05}));
  s.walls.push_back(
      core::Wall("funnel", 0,
                 core::ConeFrustumSurface{
                     .height0_m = 0, .radius0_m = 0.005, .height1_m = 0.05, .radius1_m = 0.03}));
  s.walls.front().remove_at_s = 0.5;
  LiggghtsWallSet w;
  std::string error;
  REQUIRE(LiggghtsWalls(s, "model hertz", &w, &error));
  CHECK_THAT(w.commands,
             Catch::Contains(
                 "fix w1 all wall/gran model hertz primitive type 1 zcylinder 0.05 0.1 0.2\n"));
  CHECK_THAT(w.commands,
             Catch::Contains("fix w2_mesh all mesh/surface file meshes/wall2_funnel.stl type 1\n"));
  CHECK_THAT(
      w.commands,
      Catch::Contains("fix meshes all wall/gran model hertz mesh n_meshes 1 meshes w2_mesh\n"));
  REQUIRE(w.stl_files.size() == 1);
  // Two facets per segment around; every vertex on the cone (r = 0.005 + 0.5 h).
  size_t facets = 0, pos = 0;
  while ((pos = w.stl_files[0].second.find("facet normal", pos)) != std::string::npos)
    ++facets, ++pos;
  CHECK(facets == 2 * kMeshSegments);
  std::istringstream stl(w.stl_files[0].second);
  std::string word;
  while (stl >> word) {
    if (word != "vertex") continue;
    double x, y, z;
    stl >> x >> y >> z;
    CHECK(std::hypot(x, y) == Approx(0.005 + 0.5 * z).margin(1e-12));
  }
  REQUIRE(w.removals.size() == 1);
  CHECK(w.removals[0].first == 0.5);
  CHECK(w.removals[0].second == "w1");
  // One fix wall/gran holds every mesh in LIGGGHTS: a mesh cannot be taken away alone.
  s.walls.back().remove_at_s = 0.5;
  CHECK_FALSE(LiggghtsWalls(s, "model hertz", &w, &error));
  CHECK_THAT(error, Catch::Contains("wall 'funnel'") && Catch::Contains("mesh wall taken away"));
  s.walls.back().remove_at_s = std::numeric_limits<double>::infinity();
  s.walls[0].velocity_m_s = {0, 0, 0.01};
  CHECK_FALSE(LiggghtsWalls(s, "model hertz", &w, &error));
  CHECK_THAT(error, Catch::Contains("wall 'silo'") && Catch::Contains("moving"));
}

TEST_CASE("export: a clump species becomes a multisphere template of unit-volume shape × d",
          "[unit][export]") {
  core::Scene s;
  s.materials = {{"BP", 2.5e8, 0.25, 780}};
  core::Species pair;
  pair.name = "pair";
  pair.size.diameter_m = 1e-3;
  pair.clump_shape = {{{-0.5, 0, 0}, 0.5}, {{0.5, 0, 0}, 0.5}};  // two touching spheres
  s.species = {pair};
  core::FillSpec fill(0, {0, 0, 0}, {0.01, 0.01, 0.01}, 10);
  s.fills = {fill};
  LiggghtsParticles p;
  std::string error;
  REQUIRE(LiggghtsParticleCommands(s, 1e-5, &p, &error));
  CHECK(p.clumps);
  CHECK_THAT(p.commands,
             Catch::Contains("particletemplate/multisphere") && Catch::Contains("nspheres 2"));
  CHECK_THAT(p.commands,
             Catch::Contains("insert/pack") && Catch::Contains("particles_in_region 10"));
  // Two touching unit spheres have volume 2·(π/6); at volume-equivalent d = 1 mm each member's
  // radius is 0.5 mm / 2^{1/3}, its centre 0.5 mm / 2^{1/3} from the centre of mass.
  const std::string key = "nspheres 2 ntry 1000000 spheres ";
  std::istringstream members(p.commands.substr(p.commands.find(key) + key.size()));
  for (int k = 0; k < 2; ++k) {
    double x, y, z, r;
    REQUIRE(members >> x >> y >> z >> r);
    CHECK(r == Approx(5e-4 / std::cbrt(2.0)));
    CHECK(std::sqrt(x * x + y * y + z * z) == Approx(5e-4 / std::cbrt(2.0)));
  }
  // A sphere species poured beside the clumps: LIGGGHTS would integrate one of them twice or
  // not at all.
  core::Species ball;
  ball.name = "ball";
  ball.size.diameter_m = 1e-3;
  s.species.push_back(ball);
  s.fills.push_back(core::FillSpec(1, {0, 0, 0.02}, {0.01, 0.01, 0.03}, 10));
  CHECK_FALSE(LiggghtsParticleCommands(s, 1e-5, &p, &error));
  CHECK_THAT(error, Catch::Contains("clumps and single spheres"));
}

TEST_CASE("export: calibrated parameters are applied; bad ones name the field", "[unit][export]") {
  ExperimentFile file = AorBp();
  nlohmann::json params = {
      {"format", "demcal-params/1"},
      {"interactions_pairs", {{{"materials", {"BP", "perspex"}}, {"rolling_friction", 0.2}}}}};
  std::string error;
  REQUIRE(ApplyCalibratedParams(params, "p.json", &file.model, &error));
  CHECK(file.model.pair_parameters[1].rolling_friction == 0.2);
  CHECK(file.model.pair_parameters[2].rolling_friction == 0.2);
  params["interactions_pairs"][0]["materials"][1] = "steel";
  CHECK_FALSE(ApplyCalibratedParams(params, "p.json", &file.model, &error));
  CHECK_THAT(error, Catch::Contains("p.json: field 'interactions_pairs[0].materials'"));
  params["interactions_pairs"][0] = {{"materials", {"BP", "BP"}}, {"stickiness", 1}};
  CHECK_FALSE(ApplyCalibratedParams(params, "p.json", &file.model, &error));
  CHECK_THAT(error, Catch::Contains("stickiness' is not a pair property"));
}

TEST_CASE("export: a LIGGGHTS dump reads back as a snapshot", "[unit][export]") {
  const std::string path =
      (std::filesystem::temp_directory_path() / "demcal_dump_test.liggghts").string();
  {
    std::ofstream out(path);
    out << "ITEM: TIMESTEP\n100\nITEM: NUMBER OF ATOMS\n2\nITEM: BOX BOUNDS ff ff ff\n0 1\n0 1\n0 "
           "1\n"
        << "ITEM: ATOMS id type x y z radius mass \n7 2 0.1 0.2 0.3 0.001 5e-6 \n9 1 0.4 0.5 0.6 "
           "0.002 4e-5 \n";
  }
  objectives::Snapshot s;
  std::string error;
  REQUIRE(ReadLiggghtsDump(path, &s, &error));
  REQUIRE(s.grains.size() == 2);
  CHECK(s.grains[0].id == 7);
  CHECK(s.grains[0].species == 1);
  CHECK(s.grains[1].position_m.z == 0.6);
  CHECK(s.spheres[1].radius_m == 0.002);
  {
    std::ofstream out(path);
    out << "ITEM: NUMBER OF ATOMS\n1\nITEM: ATOMS id x y z\n1 0 0 0\n";
  }
  CHECK_FALSE(ReadLiggghtsDump(path, &s, &error));
  CHECK_THAT(error, Catch::Contains("no column 'radius'"));
  std::remove(path.c_str());
}
