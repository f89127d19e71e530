#include "core/io/csv_writer.h"

#include <charconv>
#include <fstream>

#include "core/io/id_order.h"

namespace demcal::core::io {
namespace {

void PutNumber(std::string& line, double v) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  line.append(buf, r.ptr);
}

void PutNumber(std::string& line, int64_t v) {
  char buf[24];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  line.append(buf, r.ptr);
}

void PutVec(std::string& line, const Vec3& v) {
  for (int a = 0; a < 3; ++a) {
    line.push_back(',');
    PutNumber(line, v[a]);
  }
}

}  // namespace

const std::vector<std::string>& ParticleCsvColumns() {
  static const std::vector<std::string> columns = {
      "id",     "species",  "x_m",      "y_m",      "z_m",        "vx_m_s", "vy_m_s",
      "vz_m_s", "wx_rad_s", "wy_rad_s", "wz_rad_s", "diameter_m", "mass_kg"};
  return columns;
}

bool WriteParticlesCsv(const std::string& path, const Particles& p, std::string* error) {
  std::ofstream out(path, std::ios::trunc);
  if (!out) {
    if (error) *error = "cannot open '" + path + "' for writing";
    return false;
  }
  std::string line;
  for (const std::string& c : ParticleCsvColumns()) {
    if (!line.empty()) line.push_back(',');
    line += c;
  }
  out << line << '\n';
  for (size_t s : OrderById(p)) {
    line.clear();
    PutNumber(line, p.id[s]);
    line.push_back(',');
    PutNumber(line, static_cast<int64_t>(p.species[s]));
    PutVec(line, p.position_m[s]);
    PutVec(line, p.velocity_m_s[s]);
    PutVec(line, p.angular_velocity_rad_s[s]);
    line.push_back(',');
    PutNumber(line, 2 * p.radius_m[s]);
    line.push_back(',');
    PutNumber(line, p.mass_kg[s]);
    out << line << '\n';
  }
  out.flush();
  if (!out) {
    if (error) *error = "write to '" + path + "' failed (disk full?)";
    return false;
  }
  return true;
}

}  // namespace demcal::core::io
