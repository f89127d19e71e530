#include "core/io/csv_writer.h"

#include <algorithm>
#include <charconv>
#include <fstream>
#include <numeric>

#include "core/io/atomic_file.h"
#include "core/io/id_order.h"

namespace demcal::core::io {
namespace {

// One CSV line built in place (no locale, no stream formatting state).
class Row {
 public:
  Row& Put(double v) {
    char buf[32];
    const auto r = std::to_chars(buf, buf + sizeof buf, v);
    return Append(buf, r.ptr);
  }
  Row& Put(int64_t v) {
    char buf[24];
    const auto r = std::to_chars(buf, buf + sizeof buf, v);
    return Append(buf, r.ptr);
  }
  Row& Put(const Vec3& v) { return Put(v.x).Put(v.y).Put(v.z); }
  Row& Put(const std::string& s) { return Append(s.data(), s.data() + s.size()); }
  const std::string& line() const { return line_; }
  void Clear() { line_.clear(); }

 private:
  Row& Append(const char* begin, const char* end) {
    if (!line_.empty()) line_.push_back(',');
    line_.append(begin, end);
    return *this;
  }
  std::string line_;
};

// Opens `path`, writes the header and each row from `write_rows`, and checks the stream.
template <typename WriteRows>
bool WriteTable(const std::string& path, const std::vector<std::string>& columns,
                WriteRows write_rows, std::string* error) {
  AtomicFile file(path);  // a kill mid-write leaves the previous table whole
  std::ostream& out = file.stream();
  Row header;
  for (const std::string& c : columns) header.Put(c);
  out << header.line() << '\n';
  write_rows(out);
  return file.Commit(error);
}

}  // namespace

const std::vector<std::string>& ParticleCsvColumns() {
  static const std::vector<std::string> columns = {
      "id",     "species",  "x_m",      "y_m",      "z_m",        "vx_m_s",  "vy_m_s",
      "vz_m_s", "wx_rad_s", "wy_rad_s", "wz_rad_s", "diameter_m", "mass_kg", "body_id"};
  return columns;
}

const std::vector<std::string>& ClumpCsvColumns() {
  static const std::vector<std::string> columns = {
      "id",       "species",  "x_m", "y_m", "z_m", "vx_m_s", "vy_m_s",  "vz_m_s", "wx_rad_s",
      "wy_rad_s", "wz_rad_s", "qw",  "qx",  "qy",  "qz",     "mass_kg", "members"};
  return columns;
}

bool WriteParticlesCsv(const std::string& path, const Particles& p, std::string* error,
                       const Clumps* clumps) {
  return WriteTable(
      path, ParticleCsvColumns(),
      [&](std::ostream& out) {
        Row row;
        for (size_t s : OrderById(p)) {
          row.Clear();
          row.Put(p.id[s]).Put(static_cast<int64_t>(p.species[s]));
          row.Put(p.position_m[s]).Put(p.velocity_m_s[s]).Put(p.angular_velocity_rad_s[s]);
          row.Put(2 * p.radius_m[s]).Put(p.mass_kg[s]).Put(BodyId(p, clumps, s));
          out << row.line() << '\n';
        }
      },
      error);
}

bool WriteClumpsCsv(const std::string& path, const Clumps& c, std::string* error) {
  std::vector<size_t> order(c.Size());
  std::iota(order.begin(), order.end(), size_t{0});
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return c.id[a] < c.id[b]; });
  return WriteTable(
      path, ClumpCsvColumns(),
      [&](std::ostream& out) {
        Row row;
        for (size_t k : order) {
          const Quaternion& q = c.rotation[k].orientation;
          row.Clear();
          row.Put(c.id[k]).Put(static_cast<int64_t>(c.species[k]));
          row.Put(c.position_m[k]).Put(c.velocity_m_s[k]).Put(c.AngularVelocity(k));
          row.Put(q.w).Put(q.x).Put(q.y).Put(q.z).Put(c.mass_kg[k]);
          row.Put(static_cast<int64_t>(c.member_start[k + 1] - c.member_start[k]));
          out << row.line() << '\n';
        }
      },
      error);
}

}  // namespace demcal::core::io
