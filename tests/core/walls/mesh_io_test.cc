// STL reading and writing: the cube fixtures in tests/data (made by tests/data/make_cube_stl.py,
// independently of demcal's writer) read back with the right triangle count and volume, the
// format is detected by content, and every bad input ends in a status and a message naming the
// file, never an exception.
#include "core/walls/mesh_io.h"

#include <unistd.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>

#include "core/walls/triangle_mesh.h"

using namespace demcal::core;
namespace fs = std::filesystem;

namespace {

fs::path DataDir() { return fs::path(__FILE__).parent_path().parent_path().parent_path() / "data"; }

// A private scratch directory, removed at the end of the test.
struct ScratchDir {
  fs::path path = fs::temp_directory_path() / ("demcal_mesh_io_test_" + std::to_string(::getpid()));
  ScratchDir() { fs::create_directories(path); }
  ~ScratchDir() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
  std::string Write(const std::string& name, const std::string& bytes) const {
    const fs::path p = path / name;
    std::ofstream(p, std::ios::binary)
        .write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    return p.string();
  }
};

std::string ReadBytes(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

double SoupVolume(const std::vector<StlTriangle>& soup) {
  double six = 0;
  for (const StlTriangle& t : soup) six += Dot(t.v[0], Cross(t.v[1], t.v[2]));
  return six / 6;
}

std::string AsciiFacet(const std::string& a, const std::string& b, const std::string& c) {
  return "facet normal 0 0 1\n outer loop\n  vertex " + a + "\n  vertex " + b + "\n  vertex " + c +
         "\n endloop\nendfacet\n";
}

// The failed read names the file and has the expected status.
void CheckFails(const StlReadResult& r, MeshIoStatus status, const std::string& path) {
  INFO(r.message);
  CHECK(r.status == status);
  CHECK_FALSE(r.ok());
  CHECK(r.triangles.empty());
  CHECK_THAT(r.message, Catch::StartsWith(path + ": "));
}

}  // namespace

TEST_CASE("ASCII STL cube in millimetres reads back as 12 triangles of volume 1e-6 m^3",
          "[unit][geometry]") {
  const std::string path = (DataDir() / "cube_10mm_ascii.stl").string();
  const StlReadResult r = ReadStl(path, {.scale = 0.001});
  INFO(r.message);
  REQUIRE(r.ok());
  CHECK(r.format == StlFormat::kAscii);
  CHECK(r.name == "cube_10mm");
  CHECK(r.triangles.size() == 12);
  CHECK(r.triangles_in_file == 12);
  CHECK(r.degenerate_dropped == 0);
  CHECK(r.warnings.empty());
  CHECK(SoupVolume(r.triangles) == Approx(1e-6).epsilon(1e-12));

  std::string error;
  const auto mesh = TriangleMesh::FromSoup(r.triangles, {}, &error);
  REQUIRE(mesh);
  CHECK(mesh->NumVertices() == 8);
  CHECK(mesh->NumEdges() == 18);
  CHECK(mesh->IsClosed());
  CHECK(mesh->SignedVolume() == Approx(1e-6).epsilon(1e-12));
}

TEST_CASE("binary STL whose header starts with 'solid' is read as binary", "[unit][geometry]") {
  const std::string path = (DataDir() / "cube_binary_solid_header.stl").string();
  const StlReadResult r = ReadStl(path);
  INFO(r.message);
  REQUIRE(r.ok());
  CHECK(r.format == StlFormat::kBinary);
  CHECK(r.triangles.size() == 12);
  CHECK_THAT(r.name, Catch::StartsWith("solid cube exported"));
  CHECK(SoupVolume(r.triangles) == Approx(8.0).epsilon(1e-12));
  for (const StlTriangle& t : r.triangles) {
    for (const Vec3& v : t.v) {
      CHECK((v.x == 1 || v.x == 3));
      CHECK((v.y == 2 || v.y == 4));
      CHECK((v.z == 3 || v.z == 5));
    }
  }
}

TEST_CASE("binary STL writer round-trips float coordinates exactly", "[unit][geometry]") {
  ScratchDir dir;
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<float> u(-5.0f, 5.0f);
  std::vector<StlTriangle> soup(200);
  for (StlTriangle& t : soup) {
    for (Vec3& v : t.v) v = {u(rng), u(rng), u(rng)};
  }
  for (const char* header : {"demcal test", "solid header that lies"}) {
    const std::string path = (dir.path / "round_trip.stl").string();
    std::string error;
    REQUIRE(WriteBinaryStl(path, soup, &error, header));
    CHECK(fs::file_size(path) == 84 + 50 * soup.size());
    const StlReadResult r = ReadStl(path);
    INFO(r.message);
    REQUIRE(r.ok());
    CHECK(r.format == StlFormat::kBinary);
    REQUIRE(r.triangles.size() == soup.size());
    for (size_t i = 0; i < soup.size(); ++i) {
      for (int k = 0; k < 3; ++k) CHECK(r.triangles[i].v[k] == soup[i].v[k]);
    }
  }
  // The ASCII cube written as binary keeps its volume.
  const StlReadResult ascii = ReadStl((DataDir() / "cube_10mm_ascii.stl").string());
  REQUIRE(ascii.ok());
  std::string error;
  const std::string cube = (dir.path / "cube.stl").string();
  REQUIRE(WriteBinaryStl(cube, ascii.triangles, &error));
  const StlReadResult back = ReadStl(cube, {.scale = 0.001});
  REQUIRE(back.ok());
  CHECK(SoupVolume(back.triangles) == Approx(1e-6).epsilon(1e-12));
}

TEST_CASE("the writer refuses coordinates that are not finite in float32", "[unit][geometry]") {
  ScratchDir dir;
  const std::string path = (dir.path / "bad.stl").string();
  std::string error;
  std::vector<StlTriangle> soup = {{{Vec3{0, 0, 0}, Vec3{1e300, 0, 0}, Vec3{0, 1, 0}}}};
  CHECK_FALSE(WriteBinaryStl(path, soup, &error));
  CHECK_THAT(error, Catch::StartsWith(path));
  soup[0].v[1] = {NAN, 0, 0};
  CHECK_FALSE(WriteBinaryStl(path, soup, &error));
  CHECK_FALSE(WriteBinaryStl((dir.path / "no_such_dir" / "x.stl").string(), {}, &error));
}

TEST_CASE("ASCII STL variants: letter case, CRLF, '+' signs, several solids",
          "[unit][geometry]") {
  ScratchDir dir;
  const std::string facet =
      "FACET NORMAL 0 0 1\r\n OUTER LOOP\r\n  VERTEX 0 0 0\r\n"
      "  VERTEX +1.0e+0 0 0\r\n  VERTEX 0 1 -0\r\n ENDLOOP\r\nENDFACET\r\n";
  const std::string text = "SOLID first part\r\n" + facet + "ENDSOLID first part\r\n" +
                           "solid second\n" + AsciiFacet("0 0 1", "1 0 1", "0 1 1") +
                           "endsolid second\n";
  const std::string path = dir.Write("variants.stl", text);
  const StlReadResult r = ReadStl(path);
  INFO(r.message);
  REQUIRE(r.ok());
  CHECK(r.name == "first part");
  CHECK(r.triangles.size() == 2);
  CHECK(r.triangles[0].v[1] == Vec3{1, 0, 0});
  CHECK(r.warnings.empty());
}

TEST_CASE("ASCII STL cut after a facet (no endsolid) is refused as truncated, with the count",
          "[unit][geometry]") {
  ScratchDir dir;
  const std::string path = dir.Write(
      "cut.stl", "solid cut\n" + AsciiFacet("0 0 0", "1 0 0", "0 1 0") +
                     AsciiFacet("0 0 1", "1 0 1", "0 1 1"));
  const StlReadResult r = ReadStl(path);
  CHECK(r.status == MeshIoStatus::kTruncated);
  CHECK_THAT(r.message, Catch::StartsWith(path) && Catch::Contains("no final 'endsolid'") &&
                            Catch::Contains("after 2 facets"));
}

TEST_CASE("STL vertices beyond 1e6 m are refused; so are those that overflow scaling",
          "[unit][geometry]") {
  ScratchDir dir;
  const std::string far = dir.Write(
      "far.stl", "solid f\n" + AsciiFacet("0 0 0", "1e305 0 0", "0 1 0") + "endsolid f\n");
  const StlReadResult r = ReadStl(far);
  CHECK(r.status == MeshIoStatus::kNonFinite);
  CHECK_THAT(r.message, Catch::Contains("triangle 0") && Catch::Contains("1e+06 m"));
  const std::string near = dir.Write(
      "near.stl", "solid n\n" + AsciiFacet("0 0 0", "1000 0 0", "0 1000 0") + "endsolid n\n");
  CHECK(ReadStl(near, {.scale = 1e-3}).ok());
  CHECK_FALSE(ReadStl(near, {.scale = 1e4}).ok());
}

TEST_CASE("ASCII STL padded with NULs after endsolid is still ASCII", "[unit][geometry]") {
  ScratchDir dir;
  const std::string text = "solid p\n" + AsciiFacet("0 0 0", "1 0 0", "0 1 0") + "endsolid p\n";
  const std::string path = dir.Write("padded.stl", text + std::string(100, '\0') + "\x1A");
  const StlReadResult r = ReadStl(path);
  INFO(r.message);
  REQUIRE(r.ok());
  CHECK(r.format == StlFormat::kAscii);
  CHECK(r.triangles.size() == 1);
}

TEST_CASE("degenerate triangles are dropped and counted", "[unit][geometry]") {
  ScratchDir dir;
  const std::string text = "solid d\n" + AsciiFacet("0 0 0", "1 0 0", "0 1 0") +
                           AsciiFacet("0 0 0", "1 0 0", "2 0 0") +  // collinear
                           AsciiFacet("5 5 5", "5 5 5", "6 5 5") +  // repeated corner
                           AsciiFacet("0 0 1", "1 0 1", "0 1 1") + "endsolid d\n";
  const std::string path = dir.Write("some_degenerate.stl", text);
  const StlReadResult r = ReadStl(path);
  INFO(r.message);
  REQUIRE(r.ok());
  CHECK(r.triangles.size() == 2);
  CHECK(r.triangles_in_file == 4);
  CHECK(r.degenerate_dropped == 2);
  REQUIRE(r.warnings.size() == 1);
  CHECK_THAT(r.warnings[0], Catch::Contains("dropped 2 of 4") && Catch::Contains("1, 2") &&
                                Catch::StartsWith(path));
}

TEST_CASE("bad STL inputs give an error status naming the file", "[unit][geometry]") {
  ScratchDir dir;
  const std::string cube = ReadBytes(DataDir() / "cube_binary_solid_header.stl");
  REQUIRE(cube.size() == 684);

  SECTION("missing file") {
    const std::string path = (dir.path / "does_not_exist.stl").string();
    CheckFails(ReadStl(path), MeshIoStatus::kMissingFile, path);
  }
  SECTION("a directory") {
    CheckFails(ReadStl(dir.path.string()), MeshIoStatus::kMissingFile, dir.path.string());
  }
  SECTION("empty file") {
    const std::string path = dir.Write("empty.stl", "");
    CheckFails(ReadStl(path), MeshIoStatus::kEmptyFile, path);
  }
  SECTION("truncated binary, cut inside a facet") {
    const std::string path = dir.Write("truncated.stl", cube.substr(0, 84 + 50 * 5 + 20));
    const StlReadResult r = ReadStl(path);
    CheckFails(r, MeshIoStatus::kTruncated, path);
    CHECK_THAT(r.message, Catch::Contains("12 triangles"));
  }
  SECTION("truncated binary, cut inside the header") {
    const std::string path = dir.Write("truncated_header.stl", cube.substr(0, 83) + '\0');
    CheckFails(ReadStl(path), MeshIoStatus::kTruncated, path);
  }
  SECTION("binary with trailing bytes") {
    const std::string path = dir.Write("trailing.stl", cube + std::string(7, '\0') + "x");
    CheckFails(ReadStl(path), MeshIoStatus::kNotStl, path);
  }
  SECTION("text that is not STL") {
    const std::string path = dir.Write("notes.txt", "These are my notes about the funnel.\n");
    CheckFails(ReadStl(path), MeshIoStatus::kNotStl, path);
  }
  SECTION("whitespace only") {
    const std::string path = dir.Write("blank.stl", "  \n\n  \t\n");
    CheckFails(ReadStl(path), MeshIoStatus::kNotStl, path);
  }
  SECTION("random binary bytes") {
    std::mt19937 rng(3);
    std::string bytes(1000, '\0');
    for (char& c : bytes) c = static_cast<char>(rng() & 0xFF);
    const std::string path = dir.Write("random.bin", bytes);
    const StlReadResult r = ReadStl(path);
    CHECK_FALSE(r.ok());
    CHECK((r.status == MeshIoStatus::kTruncated || r.status == MeshIoStatus::kNotStl));
    CHECK_THAT(r.message, Catch::StartsWith(path + ": "));
  }
  SECTION("NaN coordinate in ASCII") {
    const std::string path = dir.Write(
        "nan.stl", "solid n\n" + AsciiFacet("0 0 0", "1 nan 0", "0 1 0") + "endsolid n\n");
    const StlReadResult r = ReadStl(path);
    CheckFails(r, MeshIoStatus::kNonFinite, path);
    CHECK_THAT(r.message, Catch::Contains("line 5") && Catch::Contains("triangle 0"));
  }
  SECTION("infinite coordinate in ASCII") {
    const std::string path = dir.Write(
        "inf.stl", "solid n\n" + AsciiFacet("0 0 0", "1 0 0", "0 1e999 0") + "endsolid n\n");
    CheckFails(ReadStl(path), MeshIoStatus::kNonFinite, path);
  }
  SECTION("NaN coordinate in binary") {
    std::string bytes = cube;
    const float nan = NAN;
    std::memcpy(bytes.data() + 84 + 50 * 3 + 12 + 4, &nan, 4);  // triangle 3, corner 0, y
    const std::string path = dir.Write("nan_binary.stl", bytes);
    const StlReadResult r = ReadStl(path);
    CheckFails(r, MeshIoStatus::kNonFinite, path);
    CHECK_THAT(r.message, Catch::Contains("triangle 3"));
  }
  SECTION("every triangle degenerate") {
    const std::string path =
        dir.Write("flat.stl", "solid f\n" + AsciiFacet("0 0 0", "1 1 1", "2 2 2") +
                                  AsciiFacet("0 0 0", "0 0 0", "0 0 0") + "endsolid f\n");
    const StlReadResult r = ReadStl(path);
    CheckFails(r, MeshIoStatus::kAllDegenerate, path);
    CHECK_THAT(r.message, Catch::Contains("all 2 triangles"));
  }
  SECTION("ASCII with zero triangles") {
    const std::string path = dir.Write("none.stl", "solid nothing\nendsolid nothing\n");
    CheckFails(ReadStl(path), MeshIoStatus::kNoTriangles, path);
  }
  SECTION("binary with zero triangles") {
    const std::string path =
        dir.Write("none_binary.stl", cube.substr(0, 80) + std::string(4, '\0'));
    CheckFails(ReadStl(path), MeshIoStatus::kNoTriangles, path);
  }
  SECTION("ASCII facet with two vertices") {
    const std::string path =
        dir.Write("two.stl",
                  "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n"
                  "endloop\nendfacet\nendsolid t\n");
    const StlReadResult r = ReadStl(path);
    CheckFails(r, MeshIoStatus::kMalformed, path);
    CHECK_THAT(r.message, Catch::Contains("line 6") && Catch::Contains("2 vertices"));
  }
  SECTION("ASCII with a word that is not a number") {
    const std::string path =
        dir.Write("word.stl", "solid w\n" + AsciiFacet("0 0 0", "1 zero 0", "0 1 0"));
    const StlReadResult r = ReadStl(path);
    CheckFails(r, MeshIoStatus::kMalformed, path);
    CHECK_THAT(r.message, Catch::Contains("'zero' is not a number"));
  }
  SECTION("ASCII ending inside a facet") {
    const std::string text = "solid t\n" + AsciiFacet("0 0 0", "1 0 0", "0 1 0");
    const std::string path = dir.Write("cut.stl", text.substr(0, text.size() - 20));
    CheckFails(ReadStl(path), MeshIoStatus::kTruncated, path);
  }
  SECTION("invalid options") {
    const std::string path = (DataDir() / "cube_10mm_ascii.stl").string();
    CheckFails(ReadStl(path, {.scale = 0}), MeshIoStatus::kInvalidOptions, path);
    CheckFails(ReadStl(path, {.scale = NAN}), MeshIoStatus::kInvalidOptions, path);
    CheckFails(ReadStl(path, {.degenerate_tolerance = -1}), MeshIoStatus::kInvalidOptions, path);
  }
}

TEST_CASE("a binary header count of 0 is inferred from the file size", "[unit][geometry]") {
  ScratchDir dir;
  std::string bytes = ReadBytes(DataDir() / "cube_binary_solid_header.stl");
  std::memset(bytes.data() + 80, 0, 4);
  const std::string path = dir.Write("zero_count.stl", bytes);
  const StlReadResult r = ReadStl(path);
  INFO(r.message);
  REQUIRE(r.ok());
  CHECK(r.triangles.size() == 12);
  REQUIRE(r.warnings.size() == 1);
  CHECK_THAT(r.warnings[0], Catch::Contains("declares 0"));
}

TEST_CASE("status names are stable", "[unit][geometry]") {
  CHECK(std::string(MeshIoStatusName(MeshIoStatus::kOk)) == "ok");
  CHECK(std::string(MeshIoStatusName(MeshIoStatus::kTruncated)) == "truncated");
  CHECK(std::string(MeshIoStatusName(MeshIoStatus::kAllDegenerate)) == "all_degenerate");
  const StlReadResult unread;
  CHECK(unread.status == MeshIoStatus::kNotRead);
  CHECK(unread.message == "ReadStl was not called");
}
