#include "core/io/vtk_writer.h"

#include "core/io/atomic_file.h"

#include <bit>
#include <charconv>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>

#include "core/io/id_order.h"

namespace demcal::core::io {
namespace {

// Appends values to the file body either as text (one value per token, shortest round-trip
// representation) or as big-endian binary.
class BodyWriter {
 public:
  BodyWriter(std::ostream& out, bool binary) : out_(out), binary_(binary) {}

  void Double(double v) {
    if (binary_) {
      uint64_t bits;
      std::memcpy(&bits, &v, sizeof bits);
      PutBigEndian(bits, 8);
    } else {
      char buf[32];
      const auto r = std::to_chars(buf, buf + sizeof buf, v);
      Token(buf, r.ptr);
    }
  }
  void Int(int32_t v) {
    if (binary_) {
      PutBigEndian(static_cast<uint32_t>(v), 4);
    } else {
      char buf[16];
      const auto r = std::to_chars(buf, buf + sizeof buf, v);
      Token(buf, r.ptr);
    }
  }
  void Vec(const Vec3& v) {
    Double(v.x);
    Double(v.y);
    Double(v.z);
    EndRecord();
  }
  // Ends a logical record (a point, a cell): a line break in ASCII files, nothing in binary.
  // Long runs of scalars wrap every kTokensPerLine values.
  void EndRecord() {
    if (!binary_ && tokens_in_line_ > 0) out_.put('\n');
    tokens_in_line_ = 0;
  }
  // Ends a data block before the next keyword line.
  void EndBlock() {
    if (binary_ || tokens_in_line_ > 0) out_.put('\n');
    tokens_in_line_ = 0;
  }

 private:
  void Token(const char* begin, const char* end) {
    if (tokens_in_line_ == kTokensPerLine) EndRecord();
    if (tokens_in_line_ > 0) out_.put(' ');
    out_.write(begin, end - begin);
    ++tokens_in_line_;
  }
  void PutBigEndian(uint64_t bits, int bytes) {
    char buf[8];
    for (int k = 0; k < bytes; ++k) buf[k] = static_cast<char>(bits >> (8 * (bytes - 1 - k)));
    out_.write(buf, bytes);
  }

  std::ostream& out_;
  bool binary_ = false;
  int tokens_in_line_ = 0;
  static constexpr int kTokensPerLine = 9;
};

std::string SnapshotName(const std::string& prefix, size_t index) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "_%06zu.vtk", index);
  return prefix + buf;
}

std::string JsonEscape(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '"' || c == '\\') out.push_back('\\');
    out.push_back(c);
  }
  return out;
}

}  // namespace

bool ParseVtkEncoding(const std::string& name, VtkOptions::Encoding* encoding) {
  if (name == "ascii")
    *encoding = VtkOptions::Encoding::kAscii;
  else if (name == "binary")
    *encoding = VtkOptions::Encoding::kBinary;
  else
    return false;
  return true;
}

bool WriteParticlesVtk(const std::string& path, const Particles& p, double time_s,
                       const VtkOptions& options, std::string* error, const Clumps* clumps) {
  AtomicFile file(path, /*binary=*/true);
  if (!file.is_open()) return file.Commit(error);  // reports why
  std::ostream& out = file.stream();
  const bool binary = options.encoding == VtkOptions::Encoding::kBinary;
  const std::vector<size_t> order = OrderById(p);
  const size_t n = order.size();
  int64_t max_id = 0;
  for (int64_t id : p.id) max_id = std::max(max_id, id);
  if (clumps)
    for (int64_t id : clumps->id) max_id = std::max(max_id, id);
  // Ids beyond int32 are stored as doubles (exact up to 2^53) rather than a 64-bit type that
  // older legacy readers do not know.
  const bool id_fits_int = max_id <= std::numeric_limits<int32_t>::max();

  BodyWriter body(out, binary);
  out << "# vtk DataFile Version 3.0\n";
  out << "demcal particles, t = " << time_s << " s\n";
  out << (binary ? "BINARY\n" : "ASCII\n");
  out << "DATASET POLYDATA\n";
  out << "FIELD FieldData 1\nTIME 1 1 double\n";
  body.Double(time_s);
  body.EndBlock();
  out << "POINTS " << n << " double\n";
  for (size_t s : order) body.Vec(p.position_m[s]);
  body.EndBlock();
  out << "VERTICES " << n << " " << 2 * n << "\n";
  for (size_t k = 0; k < n; ++k) {
    body.Int(1);
    body.Int(static_cast<int32_t>(k));
    body.EndRecord();
  }
  body.EndBlock();
  out << "POINT_DATA " << n << "\n";
  out << "SCALARS radius_m double 1\nLOOKUP_TABLE default\n";
  for (size_t s : order) body.Double(p.radius_m[s]);
  body.EndBlock();
  out << "SCALARS diameter_m double 1\nLOOKUP_TABLE default\n";
  for (size_t s : order) body.Double(2 * p.radius_m[s]);
  body.EndBlock();
  out << "VECTORS velocity_m_s double\n";
  for (size_t s : order) body.Vec(p.velocity_m_s[s]);
  body.EndBlock();
  out << "VECTORS angular_velocity_rad_s double\n";
  for (size_t s : order) body.Vec(p.angular_velocity_rad_s[s]);
  body.EndBlock();
  out << "SCALARS species int 1\nLOOKUP_TABLE default\n";
  for (size_t s : order) body.Int(p.species[s]);
  body.EndBlock();
  auto write_ids = [&](const char* name, auto id_of) {
    out << "SCALARS " << name << " " << (id_fits_int ? "int" : "double")
        << " 1\nLOOKUP_TABLE default\n";
    for (size_t s : order) {
      const int64_t id = id_of(s);
      if (id_fits_int)
        body.Int(static_cast<int32_t>(id));
      else
        body.Double(static_cast<double>(id));
    }
    body.EndBlock();
  };
  write_ids("id", [&](size_t s) { return p.id[s]; });
  write_ids("body_id", [&](size_t s) { return BodyId(p, clumps, s); });
  return file.Commit(error);
}

VtkSeries::VtkSeries(std::string directory, std::string prefix, VtkOptions options)
    : directory_(std::move(directory)), prefix_(std::move(prefix)), options_(options) {}

std::string VtkSeries::SeriesPath() const { return directory_ + "/" + prefix_ + ".vtk.series"; }

bool VtkSeries::Write(const Particles& particles, double time_s, std::string* error,
                      const Clumps* clumps) {
  const std::string name = SnapshotName(prefix_, entries_.size());
  if (!WriteParticlesVtk(directory_ + "/" + name, particles, time_s, options_, error, clumps))
    return false;
  entries_.push_back({name, time_s});
  return WriteIndex(error);
}

bool VtkSeries::Resume(std::vector<Entry> earlier, std::string* error) {
  entries_ = std::move(earlier);
  return WriteIndex(error);
}

bool VtkSeries::WriteIndex(std::string* error) const {
  const std::string path = SeriesPath();
  AtomicFile file(path);
  std::ostream& out = file.stream();
  out << "{\n  \"file-series-version\": \"1.0\",\n  \"files\": [\n";
  for (size_t k = 0; k < entries_.size(); ++k) {
    char time[32];
    const auto r = std::to_chars(time, time + sizeof time, entries_[k].time_s);
    out << "    {\"name\": \"" << JsonEscape(entries_[k].file_name)
        << "\", \"time\": " << std::string(time, r.ptr) << "}"
        << (k + 1 < entries_.size() ? "," : "") << "\n";
  }
  out << "  ]\n}\n";
  return file.Commit(error);
}

}  // namespace demcal::core::io
