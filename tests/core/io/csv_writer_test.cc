#include "core/io/csv_writer.h"

#include <catch2/catch.hpp>
#include <fstream>
#include <sstream>

#include "core/io/scratch_dir.h"
#include "core/bodies/particle_system.h"

using namespace demcal::core;
using demcal::testing::ScratchDir;

namespace {

std::vector<std::string> Split(const std::string& line) {
  std::vector<std::string> cells;
  std::stringstream s(line);
  std::string cell;
  while (std::getline(s, cell, ',')) cells.push_back(cell);
  return cells;
}

}  // namespace

TEST_CASE("the particle CSV has unit-named columns and one exact row per particle in id order",
          "[unit]") {
  Particles p;
  p.Add(9, 1, 0, 0.001, 2500, {0.1, -0.2, 1.0 / 3.0}, {1, 2, 3}, {4, 5, 6});
  p.Add(3, 0, 0, 0.0005, 1000, {0, 0, 0}, {0, 0, -0.5}, {});
  ScratchDir dir("csv");
  std::string error;
  REQUIRE(io::WriteParticlesCsv(dir.str("p.csv"), p, &error));

  std::ifstream in(dir.str("p.csv"));
  std::string header, row1, row2, extra;
  REQUIRE(std::getline(in, header));
  CHECK(header ==
        "id,species,x_m,y_m,z_m,vx_m_s,vy_m_s,vz_m_s,wx_rad_s,wy_rad_s,wz_rad_s,diameter_m,mass_kg,"
        "body_id");
  CHECK(Split(header) == io::ParticleCsvColumns());
  REQUIRE(std::getline(in, row1));
  REQUIRE(std::getline(in, row2));
  CHECK_FALSE(std::getline(in, extra));

  const auto a = Split(row1), b = Split(row2);
  REQUIRE(a.size() == io::ParticleCsvColumns().size());
  CHECK(a[0] == "3");
  CHECK(a[7] == "-0.5");
  CHECK(std::stod(a[11]) == 0.001);
  CHECK(b[0] == "9");
  CHECK(b[1] == "1");
  CHECK(std::stod(b[4]) == 1.0 / 3.0);  // shortest round-trip text reads back exactly
  CHECK(std::stod(b[10]) == 6);
  CHECK(std::stod(b[12]) == p.mass_kg[0]);
  CHECK(b[13] == "9");  // a free sphere is its own body
}

TEST_CASE("clump members name their clump as body and clumps get their own table", "[unit]") {
  // A two-sphere clump (dumbbell along x) and one free sphere, through the engine's own
  // particle system so ids and member slots are as in a run.
  std::vector<Species> species(2);
  species[0].name = "free";
  species[1].name = "dumbbell";
  species[1].clump_shape = {{{-0.5, 0, 0}, 0.5}, {{0.5, 0, 0}, 0.5}};
  ParticleSystem system;
  std::string error;
  REQUIRE(system.SetSpecies(species, &error));
  system.Add(0, 0, 1000, 0.002, {0, 0, 0}, {}, {}, Quaternion());
  system.Add(1, 0, 1000, 0.002, {0.01, 0, 0}, {0, 0, -1}, {}, Quaternion());
  REQUIRE(system.clumps.Size() == 1);
  ScratchDir dir("csv_clumps");
  REQUIRE(io::WriteParticlesCsv(dir.str("p.csv"), system.spheres, &error, &system.clumps));
  REQUIRE(io::WriteClumpsCsv(dir.str("c.csv"), system.clumps, &error));

  std::ifstream spheres(dir.str("p.csv"));
  std::string line;
  std::getline(spheres, line);
  int members = 0;
  while (std::getline(spheres, line)) {
    const auto cells = Split(line);
    if (cells[1] == "1") {
      ++members;
      CHECK(cells[13] == std::to_string(system.clumps.id[0]));
    } else {
      CHECK(cells[13] == cells[0]);
    }
  }
  CHECK(members == 2);

  std::ifstream clumps(dir.str("c.csv"));
  std::getline(clumps, line);
  CHECK(Split(line) == io::ClumpCsvColumns());
  REQUIRE(std::getline(clumps, line));
  const auto c = Split(line);
  REQUIRE(c.size() == io::ClumpCsvColumns().size());
  CHECK(c[0] == std::to_string(system.clumps.id[0]));
  CHECK(std::stod(c[2]) == 0.01);
  CHECK(std::stod(c[7]) == -1);  // vz
  CHECK(std::stod(c[11]) == 1);  // qw of the identity orientation
  CHECK(std::stod(c[15]) == system.clumps.mass_kg[0]);
  CHECK(c[16] == "2");
  CHECK_FALSE(std::getline(clumps, line));
}

TEST_CASE("CSV writing to a missing directory fails with a message naming the path", "[unit]") {
  std::string error;
  CHECK_FALSE(io::WriteParticlesCsv("/nonexistent-dir/p.csv", Particles{}, &error));
  CHECK_THAT(error, Catch::Contains("/nonexistent-dir/p.csv"));
}
