#include "workflow/export/liggghts_dump.h"

#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <vector>

namespace demcal::workflow {
namespace {

bool Fail(const std::string& path, int line, const std::string& what, std::string* error) {
  *error = "LIGGGHTS dump '" + path + "', line " + std::to_string(line) + ": " + what;
  return false;
}

}  // namespace

bool ReadLiggghtsDump(const std::string& path, objectives::Snapshot* out, std::string* error) {
  std::ifstream in(path);
  if (!in) {
    *error = "cannot read LIGGGHTS dump '" + path + "'";
    return false;
  }
  std::string text;
  int line_no = 0, atoms_left = -1;
  double time_step = 0;
  std::map<std::string, int> col;
  objectives::Snapshot snap;
  bool read_any = false;
  while (std::getline(in, text)) {
    ++line_no;
    if (text.rfind("ITEM: TIMESTEP", 0) == 0) {
      if (!std::getline(in, text))
        return Fail(path, line_no, "no step after ITEM: TIMESTEP", error);
      ++line_no;
      time_step = std::atof(text.c_str());
      continue;
    }
    if (text.rfind("ITEM: NUMBER OF ATOMS", 0) == 0) {
      if (!std::getline(in, text)) return Fail(path, line_no, "no count", error);
      ++line_no;
      atoms_left = std::atoi(text.c_str());
      continue;
    }
    if (text.rfind("ITEM: ATOMS", 0) == 0) {
      std::istringstream names(text.substr(11));
      col.clear();
      std::string name;
      for (int k = 0; names >> name; ++k) col[name] = k;
      for (const char* need : {"id", "x", "y", "z", "radius"})
        if (!col.count(need))
          return Fail(path, line_no, std::string("no column '") + need + "'", error);
      snap = {};
      snap.time_s = time_step;  // the step number; callers know Δt
      for (int a = 0; a < atoms_left; ++a) {
        if (!std::getline(in, text))
          return Fail(path, line_no, "fewer atoms than announced", error);
        ++line_no;
        std::istringstream row(text);
        std::vector<double> v;
        double x;
        while (row >> x) v.push_back(x);
        if (v.size() < col.size() || !std::isfinite(v[col["x"]]))
          return Fail(path, line_no, "a row with fewer numbers than columns", error);
        objectives::Grain g;
        g.id = static_cast<int64_t>(v[col["id"]]);
        g.species = col.count("type") ? static_cast<int>(v[col["type"]]) - 1 : 0;
        g.position_m = {v[col["x"]], v[col["y"]], v[col["z"]]};
        if (col.count("vx")) g.velocity_m_s = {v[col["vx"]], v[col["vy"]], v[col["vz"]]};
        g.radius_m = v[col["radius"]];
        g.mass_kg = col.count("mass") ? v[col["mass"]] : 0;
        snap.spheres.push_back({g.position_m, g.radius_m, static_cast<int>(snap.grains.size())});
        snap.grains.push_back(g);
      }
      read_any = true;
    }
  }
  if (!read_any) return Fail(path, line_no, "no ITEM: ATOMS section", error);
  *out = std::move(snap);
  return true;
}

}  // namespace demcal::workflow
