#include "core/walls/mesh_io.h"

#include <algorithm>
#include <bit>
#include <cctype>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <cstdio>
#include <limits>

#include "core/limits/physical_limits.h"
#include "core/walls/stl_ascii_parser.h"

namespace demcal::core {
namespace {

constexpr size_t kHeaderBytes = 80;
// The coordinate bound of every scene position (physical_limits.h); it also keeps products of
// coordinates (areas, cross products, squared distances) finite.
constexpr double kMaxCoordinateM = limits::kCoordinate.hi;

std::string FormatG(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", v);
  return text;
}
constexpr size_t kBinaryPreamble = 84;  // header + uint32 triangle count
constexpr size_t kBinaryFacetBytes = 50;

StlReadResult Failure(MeshIoStatus status, const std::string& source, const std::string& what) {
  StlReadResult r;
  r.status = status;
  r.message = source + ": " + what;
  return r;
}

uint32_t ReadU32(const char* p) {
  const auto* b = reinterpret_cast<const unsigned char*>(p);
  return uint32_t{b[0]} | uint32_t{b[1]} << 8 | uint32_t{b[2]} << 16 | uint32_t{b[3]} << 24;
}

float ReadF32(const char* p) { return std::bit_cast<float>(ReadU32(p)); }

void WriteU32(char* p, uint32_t v) {
  for (int i = 0; i < 4; ++i) p[i] = static_cast<char>((v >> (8 * i)) & 0xFFu);
}

void WriteF32(char* p, float v) { WriteU32(p, std::bit_cast<uint32_t>(v)); }

// Text bytes: printable ASCII, whitespace, and bytes >= 0x80 (UTF-8 names in "solid" lines).
bool IsTextByte(unsigned char c) {
  return (c >= 0x20 && c != 0x7F) || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f';
}

// ASCII exporters sometimes pad with NULs or end with a DOS end-of-file mark (0x1A).
std::string_view TrimTrailingPadding(std::string_view s) {
  while (!s.empty() && (s.back() == '\0' || s.back() == '\x1A')) s.remove_suffix(1);
  return s;
}

bool LooksLikeText(std::string_view s) {
  return std::all_of(s.begin(), s.end(), [](char c) { return IsTextByte(c); });
}

// True if the last non-blank line starts with "endsolid" (any case).
bool EndsWithEndsolid(std::string_view s) {
  const size_t end = s.find_last_not_of(" \t\r\n\v\f");
  if (end == std::string_view::npos) return false;
  s = s.substr(0, end + 1);
  const size_t newline = s.find_last_of('\n');
  std::string_view line = newline == std::string_view::npos ? s : s.substr(newline + 1);
  line.remove_prefix(std::min(line.size(), line.find_first_not_of(" \t\r\v\f")));
  constexpr std::string_view kEndsolid = "endsolid";
  return line.size() >= kEndsolid.size() &&
         std::equal(kEndsolid.begin(), kEndsolid.end(), line.begin(), [](char k, char c) {
           return k == std::tolower(static_cast<unsigned char>(c));
         });
}

// ASCII text, possibly padded after its final "endsolid" line.
bool IsAsciiText(std::string_view bytes) {
  if (LooksLikeText(bytes)) return true;
  const std::string_view trimmed = TrimTrailingPadding(bytes);
  return trimmed.size() < bytes.size() && LooksLikeText(trimmed) && EndsWithEndsolid(trimmed);
}

std::string HeaderText(std::string_view header) {
  std::string text;
  for (char c : header) {
    if (c == '\0') break;
    text.push_back(IsTextByte(static_cast<unsigned char>(c)) && c != '\n' && c != '\r' ? c : ' ');
  }
  const size_t end = text.find_last_not_of(' ');
  return end == std::string::npos ? std::string() : text.substr(0, end + 1);
}

StlReadResult ParseBinary(std::string_view bytes, uint32_t count, const std::string& source) {
  StlReadResult r;
  r.format = StlFormat::kBinary;
  r.name = HeaderText(bytes.substr(0, kHeaderBytes));
  r.triangles.resize(count);
  for (uint32_t i = 0; i < count; ++i) {
    const char* facet = bytes.data() + kBinaryPreamble + kBinaryFacetBytes * size_t{i};
    StlTriangle& t = r.triangles[i];
    for (int k = 0; k < 3; ++k) {
      const char* p = facet + 12 * (k + 1);  // skip the stored normal
      t.v[k] = {ReadF32(p), ReadF32(p + 4), ReadF32(p + 8)};
      if (!IsFinite(t.v[k])) {
        return Failure(MeshIoStatus::kNonFinite, source,
                       "binary STL triangle " + std::to_string(i) + " (of " +
                           std::to_string(count) + ") has a non-finite (NaN or infinite) " +
                           "coordinate");
      }
    }
  }
  return r;
}

// Checks, scales and filters a parsed soup; `r` already holds the triangles in file units.
StlReadResult Finish(StlReadResult r, const StlReadOptions& options, const std::string& source) {
  const char* kind = r.format == StlFormat::kBinary ? "binary STL" : "ASCII STL";
  r.triangles_in_file = static_cast<int64_t>(r.triangles.size());
  if (r.triangles.empty()) {
    return Failure(MeshIoStatus::kNoTriangles, source,
                   std::string(kind) + " file contains no triangles");
  }
  std::vector<StlTriangle> kept;
  kept.reserve(r.triangles.size());
  std::string first_dropped;
  for (size_t i = 0; i < r.triangles.size(); ++i) {
    StlTriangle t = r.triangles[i];
    for (Vec3& v : t.v) v *= options.scale;
    if (!IsFinite(t.v[0]) || !IsFinite(t.v[1]) || !IsFinite(t.v[2])) {
      return Failure(MeshIoStatus::kNonFinite, source,
                     "triangle " + std::to_string(i) + " overflows after scaling by " +
                         FormatG(options.scale));
    }
    for (const Vec3& v : t.v)
      if (std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)}) > kMaxCoordinateM)
        return Failure(MeshIoStatus::kNonFinite, source,
                       "triangle " + std::to_string(i) + " has a vertex at " +
                           FormatG(std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)})) +
                           " m (after scaling by " + FormatG(options.scale) +
                           "); allowed: |coordinate| <= " + FormatG(kMaxCoordinateM) +
                           " m (check the STL's units and scale)");
    if (IsDegenerateTriangle(t, options.degenerate_tolerance)) {
      if (++r.degenerate_dropped <= 5) {
        first_dropped += (first_dropped.empty() ? "" : ", ") + std::to_string(i);
      }
      continue;
    }
    kept.push_back(t);
  }
  if (kept.empty()) {
    return Failure(
        MeshIoStatus::kAllDegenerate, source,
        "all " + std::to_string(r.triangles_in_file) + " triangles are degenerate (zero area)");
  }
  if (r.degenerate_dropped > 0) {
    r.warnings.push_back(source + ": dropped " + std::to_string(r.degenerate_dropped) + " of " +
                         std::to_string(r.triangles_in_file) +
                         " triangles as degenerate (zero area); first indices: " + first_dropped);
  }
  r.triangles = std::move(kept);
  r.status = MeshIoStatus::kOk;
  r.message = source + ": read " + std::to_string(r.triangles.size()) + " triangles (" + kind +
              (r.degenerate_dropped > 0
                   ? ", " + std::to_string(r.degenerate_dropped) + " degenerate dropped"
                   : std::string()) +
              ")";
  return r;
}

StlReadResult ParseBinaryChecked(std::string_view bytes, const std::string& source,
                                 const StlReadOptions& options) {
  if (bytes.size() < kBinaryPreamble) {
    return Failure(MeshIoStatus::kTruncated, source,
                   "binary data of " + std::to_string(bytes.size()) +
                       " bytes is shorter than the 84-byte binary STL header (truncated, or "
                       "not an STL file)");
  }
  uint64_t count = ReadU32(bytes.data() + kHeaderBytes);
  const uint64_t payload = bytes.size() - kBinaryPreamble;
  std::vector<std::string> warnings;
  if (count == 0 && payload > 0 && payload % kBinaryFacetBytes == 0) {
    // Streaming writers sometimes leave the count at 0; the size says how many facets follow.
    count = payload / kBinaryFacetBytes;
    warnings.push_back(source + ": binary STL header declares 0 triangles; using the " +
                       std::to_string(count) + " that the file size implies");
  }
  const uint64_t expected = kBinaryPreamble + kBinaryFacetBytes * count;
  if (bytes.size() < expected) {
    return Failure(MeshIoStatus::kTruncated, source,
                   "truncated binary STL: the header declares " + std::to_string(count) +
                       " triangles (" + std::to_string(expected) + " bytes) but the file has " +
                       std::to_string(bytes.size()) + " bytes");
  }
  if (bytes.size() > expected) {
    return Failure(MeshIoStatus::kNotStl, source,
                   "not an STL file: not ASCII STL, and its size (" + std::to_string(bytes.size()) +
                       " bytes) does not match 84 + 50 x " + std::to_string(count) +
                       " triangles declared in a binary STL header");
  }
  StlReadResult r = ParseBinary(bytes, static_cast<uint32_t>(count), source);
  if (r.status == MeshIoStatus::kNonFinite) return r;
  r.warnings = std::move(warnings);
  return Finish(std::move(r), options, source);
}

}  // namespace

const char* MeshIoStatusName(MeshIoStatus status) {
  switch (status) {
    case MeshIoStatus::kOk:
      return "ok";
    case MeshIoStatus::kNotRead:
      return "not_read";
    case MeshIoStatus::kInvalidOptions:
      return "invalid_options";
    case MeshIoStatus::kMissingFile:
      return "missing_file";
    case MeshIoStatus::kEmptyFile:
      return "empty_file";
    case MeshIoStatus::kTruncated:
      return "truncated";
    case MeshIoStatus::kNotStl:
      return "not_stl";
    case MeshIoStatus::kMalformed:
      return "malformed";
    case MeshIoStatus::kNonFinite:
      return "non_finite";
    case MeshIoStatus::kNoTriangles:
      return "no_triangles";
    case MeshIoStatus::kAllDegenerate:
      return "all_degenerate";
    case MeshIoStatus::kWriteFailed:
      return "write_failed";
  }
  return "unknown";
}

bool StlReadOptions::IsValid(std::string* error) const {
  if (!std::isfinite(scale) || !(scale > 0)) {
    if (error)
      *error = "StlReadOptions::scale must be finite and > 0, got " + std::to_string(scale);
    return false;
  }
  if (!(degenerate_tolerance >= 0 && degenerate_tolerance < 1)) {
    if (error) *error = "StlReadOptions::degenerate_tolerance must be in [0, 1)";
    return false;
  }
  return true;
}

bool IsDegenerateTriangle(const StlTriangle& t, double tolerance) {
  const Vec3 e0 = t.v[1] - t.v[0], e1 = t.v[2] - t.v[1], e2 = t.v[0] - t.v[2];
  const double longest2 = std::max({Norm2(e0), Norm2(e1), Norm2(e2)});
  return longest2 == 0 || Norm(Cross(e0, -e2)) <= tolerance * longest2;
}

StlReadResult ParseStl(std::string_view bytes, const std::string& source,
                       const StlReadOptions& options) {
  std::string options_error;
  if (!options.IsValid(&options_error)) {
    return Failure(MeshIoStatus::kInvalidOptions, source, options_error);
  }
  if (bytes.empty()) return Failure(MeshIoStatus::kEmptyFile, source, "file is empty (0 bytes)");

  // Binary first: an exact size match is decisive even if the header starts with "solid".
  if (bytes.size() >= kBinaryPreamble) {
    const uint64_t count = ReadU32(bytes.data() + kHeaderBytes);
    if (bytes.size() == kBinaryPreamble + kBinaryFacetBytes * count) {
      return ParseBinaryChecked(bytes, source, options);
    }
  }
  if (!IsAsciiText(bytes)) return ParseBinaryChecked(bytes, source, options);
  const std::string_view text = TrimTrailingPadding(bytes);
  if (!StartsWithSolidKeyword(text)) {
    const bool blank = text.find_first_not_of(" \t\r\n\v\f") == std::string_view::npos;
    return Failure(MeshIoStatus::kNotStl, source,
                   blank ? std::string("not an STL file: it holds only whitespace")
                         : std::string("not an STL file: text that does not start with 'solid', "
                                       "and not a binary STL"));
  }
  StlReadResult r;
  r.format = StlFormat::kAscii;
  std::string what;
  const MeshIoStatus status = ParseAsciiStl(text, &r.triangles, &r.name, &r.warnings, &what);
  if (status != MeshIoStatus::kOk) return Failure(status, source, what);
  for (std::string& w : r.warnings) w = source + ": " + w;
  return Finish(std::move(r), options, source);
}

StlReadResult ReadStl(const std::string& path, const StlReadOptions& options) {
  try {
    std::error_code ec;
    const auto status = std::filesystem::status(path, ec);
    if (ec || !std::filesystem::exists(status)) {
      return Failure(MeshIoStatus::kMissingFile, path, "no such file");
    }
    if (!std::filesystem::is_regular_file(status)) {
      return Failure(MeshIoStatus::kMissingFile, path, "not a regular file");
    }
    // 1 GiB: about 20 million binary triangles, far beyond a wall mesh; refused before reading.
    constexpr uintmax_t kMaxStlBytes = uintmax_t{1} << 30;
    const uintmax_t size = std::filesystem::file_size(path, ec);
    if (!ec && size > kMaxStlBytes)
      return Failure(MeshIoStatus::kNotStl, path,
                     "the file holds " + std::to_string(size) +
                         " bytes; allowed: at most 1 GiB for a wall mesh");
    std::ifstream in(path, std::ios::binary);
    if (!in) return Failure(MeshIoStatus::kMissingFile, path, "cannot open the file for reading");
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (in.bad()) return Failure(MeshIoStatus::kMissingFile, path, "read error");
    return ParseStl(bytes, path, options);
  } catch (const std::exception& e) {
    return Failure(MeshIoStatus::kMissingFile, path, std::string("cannot read: ") + e.what());
  }
}

bool WriteBinaryStl(const std::string& path, std::span<const StlTriangle> triangles,
                    std::string* error, std::string_view header) {
  auto fail = [&](const std::string& what) {
    if (error) *error = path + ": " + what;
    return false;
  };
  if (triangles.size() > std::numeric_limits<uint32_t>::max()) {
    return fail("too many triangles for binary STL");
  }
  std::string bytes(kBinaryPreamble + kBinaryFacetBytes * triangles.size(), '\0');
  std::copy_n(header.data(), std::min(header.size(), kHeaderBytes), bytes.data());
  WriteU32(bytes.data() + kHeaderBytes, static_cast<uint32_t>(triangles.size()));
  for (size_t i = 0; i < triangles.size(); ++i) {
    const StlTriangle& t = triangles[i];
    char* facet = bytes.data() + kBinaryPreamble + kBinaryFacetBytes * i;
    const Vec3 n = Cross(t.v[1] - t.v[0], t.v[2] - t.v[0]);
    const double len = Norm(n);
    const Vec3 unit = len > 0 ? n / len : Vec3{};
    for (int c = 0; c < 3; ++c) WriteF32(facet + 4 * c, static_cast<float>(unit[c]));
    for (int k = 0; k < 3; ++k) {
      for (int c = 0; c < 3; ++c) {
        const float x = static_cast<float>(t.v[k][c]);
        if (!std::isfinite(x)) {
          return fail("triangle " + std::to_string(i) +
                      " has a coordinate that is not finite in float32");
        }
        WriteF32(facet + 12 * (k + 1) + 4 * c, x);
      }
    }
  }
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) return fail("cannot open the file for writing");
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  out.close();
  if (!out) return fail("write error");
  return true;
}

}  // namespace demcal::core
