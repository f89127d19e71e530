#pragma once
// STL reading and writing: a triangle soup (three corners per triangle, no shared vertices) for
// wall meshes. ReadStl accepts ASCII and binary STL and tells them apart by content, not by the
// first word: a binary file whose size is exactly 84 + 50·n (n = the triangle count in its
// header) is binary even if its 80-byte header starts with "solid", as many exporters write.
//
// Units: STL is unitless. Coordinates are multiplied by StlReadOptions::scale to give metres
// (1 for files in metres, 0.001 for millimetres). Facet normals stored in the file are ignored:
// a triangle's orientation is its corner order (counter-clockwise seen from the front).
//
// Errors: no exceptions escape and nothing aborts. A failed read returns a status other than kOk
// and a message that starts with the file name: missing or unreadable file, empty file, truncated
// binary or ASCII data (with the facet count read), not STL, malformed ASCII (with the line
// number), non-finite coordinates or coordinates beyond 1e6 m (with the triangle number), no triangles, or every triangle degenerate. Degenerate (zero-area)
// triangles are dropped from a good read; their count is in degenerate_dropped and a warning.
//
// Thread-safety: free functions, no shared state.
//
// Usage:
//   const StlReadResult stl = ReadStl("funnel_mm.stl", {.scale = 0.001});
//   if (!stl.ok()) return Fail(stl.message);
//   for (const StlTriangle& t : stl.triangles) ...   // metres
#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/math/vec3.h"

namespace demcal::core {

// One triangle of a soup: its three corners, counter-clockwise seen from the front.
struct StlTriangle {
  std::array<Vec3, 3> v;
};

enum class MeshIoStatus {
  kOk,
  kNotRead,         // ReadStl was not called (the default of a result)
  kInvalidOptions,  // StlReadOptions::IsValid failed; nothing was read
  kMissingFile,     // does not exist, is not a regular file, or cannot be opened
  kEmptyFile,       // zero bytes
  kTruncated,       // binary shorter than its header promises, ASCII without its 'endsolid'
  kNotStl,          // neither ASCII STL ("solid" ...) nor a binary STL of consistent size
  kMalformed,       // ASCII STL with a syntax error
  kNonFinite,       // a NaN or infinite coordinate
  kNoTriangles,     // a well-formed file with zero triangles
  kAllDegenerate,   // every triangle has zero area
  kWriteFailed,     // WriteBinaryStl could not write
};

// Stable lower-case names: ok, not_read, invalid_options, missing_file, ...
const char* MeshIoStatusName(MeshIoStatus status);

enum class StlFormat { kUnknown, kAscii, kBinary };

struct StlReadOptions {
  // Multiplies every coordinate (file units → metres). Finite and > 0. Default 1 (metres).
  double scale = 1.0;
  // A triangle is degenerate (zero area: repeated or collinear corners) when twice its area,
  // |(v1 − v0) × (v2 − v0)|, is at most tolerance · (longest edge)². In [0, 1). Default 1e-10.
  double degenerate_tolerance = 1e-10;

  bool IsValid(std::string* error) const;
};

struct StlReadResult {
  MeshIoStatus status = MeshIoStatus::kNotRead;
  std::string message = "ReadStl was not called";
  StlFormat format = StlFormat::kUnknown;
  std::string name;                    // ASCII solid name, or printable text of a binary header
  std::vector<StlTriangle> triangles;  // metres; degenerate ones removed
  int64_t triangles_in_file = 0;       // as read, before dropping degenerate ones
  int64_t degenerate_dropped = 0;
  std::vector<std::string> warnings;  // recoverable oddities (dropped triangles, no endsolid)

  bool ok() const { return status == MeshIoStatus::kOk; }
};

// Reads an STL file. See the file comment for the format detection and the errors.
StlReadResult ReadStl(const std::string& path, const StlReadOptions& options = {});

// Parses STL bytes already in memory; `source_name` stands for the file name in messages.
StlReadResult ParseStl(std::string_view bytes, const std::string& source_name,
                       const StlReadOptions& options = {});

// True if the triangle has zero area in the sense of StlReadOptions::degenerate_tolerance.
bool IsDegenerateTriangle(const StlTriangle& triangle, double tolerance);

// Writes a binary STL (little-endian, float32 coordinates, facet normals from the corner order).
// `header` fills the 80-byte header (truncated, zero padded); the STL convention is that it does
// not start with "solid", but this writer does not enforce it. Returns false and sets *error
// (naming the file) on a non-finite coordinate or an I/O failure.
bool WriteBinaryStl(const std::string& path, std::span<const StlTriangle> triangles,
                    std::string* error, std::string_view header = "demcal binary STL");

}  // namespace demcal::core
