#include "bench/liggghts_inputs.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numbers>

namespace demcal::bench {

bool WriteLiggghtsInputs(const std::string& dir, const core::Particles& p, const core::Vec3& lo,
                         const core::Vec3& hi, const LiggghtsVars& vars, std::string* error) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  const std::string data_path = dir + "/initial.data", vars_path = dir + "/case.vars";
  std::ofstream data(data_path), list(vars_path);
  if (!data || !list) {
    *error = "cannot write " + (data ? vars_path : data_path);
    return false;
  }
  bool any_fixed = false;
  for (size_t i = 0; i < p.Size() && !any_fixed; ++i) any_fixed = p.IsFixed(i);
  char line[256];
  // One atom type per kind present: the decks give each type its material values.
  data << "demcal_bench initial state (bench/liggghts_inputs.cc)\n\n"
       << p.Size() << " atoms\n" << (any_fixed ? 2 : 1) << " atom types\n\n";
  // %.17g: the same doubles in both codes.
  std::snprintf(line, sizeof line,
                "%.17g %.17g xlo xhi\n%.17g %.17g ylo yhi\n%.17g %.17g zlo zhi\n", lo.x, hi.x,
                lo.y, hi.y, lo.z, hi.z);
  data << line << "\nAtoms\n\n";
  for (size_t i = 0; i < p.Size(); ++i) {
    const double d = 2 * p.radius_m[i];
    const double density = p.mass_kg[i] / (std::numbers::pi / 6 * d * d * d);
    std::snprintf(line, sizeof line, "%zu %d %.17g %.17g %.17g %.17g %.17g\n", i + 1,
                  p.IsFixed(i) ? 2 : 1, d, density, p.position_m[i].x, p.position_m[i].y,
                  p.position_m[i].z);
    data << line;
  }
  data << "\nVelocities\n\n";
  for (size_t i = 0; i < p.Size(); ++i) {
    const core::Vec3& v = p.velocity_m_s[i];
    const core::Vec3& w = p.angular_velocity_rad_s[i];
    std::snprintf(line, sizeof line, "%zu %.17g %.17g %.17g %.17g %.17g %.17g\n", i + 1, v.x, v.y,
                  v.z, w.x, w.y, w.z);
    data << line;
  }
  for (const auto& [name, value] : vars) {
    std::snprintf(line, sizeof line, "%s %.17g\n", name.c_str(), value);
    list << line;
  }
  data.close();
  list.close();
  if (!data || !list) {
    *error = "error writing " + data_path + " or " + vars_path;
    return false;
  }
  return true;
}

}  // namespace demcal::bench
