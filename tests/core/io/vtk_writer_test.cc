#include "core/io/vtk_writer.h"

#include <catch2/catch.hpp>
#include <fstream>
#include <nlohmann/json.hpp>

#include "core/io/legacy_vtk_reader.h"
#include "core/io/scratch_dir.h"
#include "core/bodies/particle_system.h"

using namespace demcal::core;
using namespace demcal::core::io;
using demcal::testing::ReadLegacyVtk;
using demcal::testing::ScratchDir;

namespace {

// Three spheres stored out of id order, as the engine's spatial reordering leaves them.
Particles ThreeSpheres() {
  Particles p;
  p.Add(7, 1, 0, 0.0015, 2500, {0.1, 0.2, 0.3}, {1, 2, 3}, {4, 5, 6});
  p.Add(2, 0, 0, 0.001, 2500, {-1.0 / 3.0, 1e-9, 2.5}, {0, 0, -1}, {0, 0, 0});
  p.Add(5, 0, 0, 0.00125, 2500, {0, 0, 0}, {}, {0.5, 0, 0});
  return p;
}

void CheckRoundTrip(VtkOptions::Encoding encoding) {
  ScratchDir dir("vtk");
  const Particles p = ThreeSpheres();
  const std::string path = dir.str("p.vtk");
  std::string error;
  REQUIRE(WriteParticlesVtk(path, p, 0.125, {encoding}, &error));
  const auto v = ReadLegacyVtk(path);
  CHECK(v.binary == (encoding == VtkOptions::Encoding::kBinary));
  CHECK(v.dataset == "POLYDATA");
  REQUIRE(v.points.size() == 9);  // three points
  CHECK(v.point_data_count == 3);
  CHECK(v.field_data.at("TIME") == std::vector<double>{0.125});
  // Points come in id order (2, 5, 7) and are exact (shortest round-trip text or raw bits).
  CHECK(v.point_data.at("id") == std::vector<double>{2, 5, 7});
  CHECK(v.point_data.at("body_id") == std::vector<double>{2, 5, 7});  // free spheres
  CHECK(v.points[0] == -1.0 / 3.0);
  CHECK(v.points[1] == 1e-9);
  CHECK(v.points[6] == 0.1);
  CHECK(v.point_data.at("radius_m") == std::vector<double>{0.001, 0.00125, 0.0015});
  CHECK(v.point_data.at("diameter_m") == std::vector<double>{0.002, 0.0025, 0.003});
  CHECK(v.point_data.at("species") == std::vector<double>{0, 0, 1});
  CHECK(v.point_data_type.at("species") == "int");
  CHECK(v.point_data.at("velocity_m_s") == std::vector<double>{0, 0, -1, 0, 0, 0, 1, 2, 3});
  CHECK(v.point_data.at("angular_velocity_rad_s") ==
        std::vector<double>{0, 0, 0, 0.5, 0, 0, 4, 5, 6});
  // One vertex cell per point so ParaView draws them without a glyph filter.
  CHECK(v.vertices == std::vector<int32_t>{1, 0, 1, 1, 1, 2});
}

}  // namespace

TEST_CASE("ASCII VTK snapshots parse back point for point", "[unit]") {
  CheckRoundTrip(VtkOptions::Encoding::kAscii);
}

TEST_CASE("binary VTK snapshots are big-endian and parse back point for point", "[unit]") {
  CheckRoundTrip(VtkOptions::Encoding::kBinary);
}

TEST_CASE("a VTK snapshot of an empty particle set is a valid file with zero points", "[unit]") {
  ScratchDir dir("vtk_empty");
  std::string error;
  REQUIRE(WriteParticlesVtk(dir.str("e.vtk"), Particles{}, 0, {}, &error));
  const auto v = ReadLegacyVtk(dir.str("e.vtk"));
  CHECK(v.points.empty());
  CHECK(v.point_data_count == 0);
}

TEST_CASE("VTK writing to a missing directory fails with a message naming the path", "[unit]") {
  std::string error;
  CHECK_FALSE(WriteParticlesVtk("/nonexistent-dir/x.vtk", ThreeSpheres(), 0, {}, &error));
  CHECK_THAT(error, Catch::Contains("/nonexistent-dir/x.vtk"));
}

TEST_CASE("a VTK series indexes every snapshot with its time", "[unit]") {
  ScratchDir dir("vtk_series");
  VtkSeries series(dir.str(), "particles", {VtkOptions::Encoding::kAscii});
  Particles p = ThreeSpheres();
  std::string error;
  REQUIRE(series.Write(p, 0.0, &error));
  p.position_m[0].z = 0.25;
  REQUIRE(series.Write(p, 0.05, &error));
  const nlohmann::json index = nlohmann::json::parse(std::ifstream(series.SeriesPath()));
  CHECK(index["file-series-version"] == "1.0");
  REQUIRE(index["files"].size() == 2);
  CHECK(index["files"][0]["name"] == "particles_000000.vtk");
  CHECK(index["files"][1]["name"] == "particles_000001.vtk");
  CHECK(index["files"][1]["time"].get<double>() == 0.05);
  const auto second = ReadLegacyVtk(dir.str("particles_000001.vtk"));
  CHECK(second.points[8] == 0.25);  // id 7 is the third point
}

TEST_CASE("VTK snapshots give clump members their clump's id as body_id", "[unit]") {
  std::vector<Species> species(1);
  species[0].clump_shape = {{{-0.5, 0, 0}, 0.5}, {{0.5, 0, 0}, 0.5}};
  ParticleSystem system;
  std::string error;
  REQUIRE(system.SetSpecies(species, &error));
  system.Add(0, 0, 1000, 0.002, {0, 0, 0}, {}, {}, Quaternion());
  ScratchDir dir("vtk_clump");
  REQUIRE(WriteParticlesVtk(dir.str("c.vtk"), system.spheres, 0, {}, &error, &system.clumps));
  const auto v = ReadLegacyVtk(dir.str("c.vtk"));
  REQUIRE(v.point_data_count == 2);  // the members are the points
  const double clump_id = static_cast<double>(system.clumps.id[0]);
  CHECK(v.point_data.at("body_id") == std::vector<double>{clump_id, clump_id});
}

TEST_CASE("VTK encodings are parsed by name", "[unit]") {
  VtkOptions::Encoding e = VtkOptions::Encoding::kBinary;
  CHECK(io::ParseVtkEncoding("ascii", &e));
  CHECK(e == VtkOptions::Encoding::kAscii);
  CHECK(io::ParseVtkEncoding("binary", &e));
  CHECK(e == VtkOptions::Encoding::kBinary);
  CHECK_FALSE(io::ParseVtkEncoding("xml", &e));
}
