#include "calibrate/liggghts_export.h"

#include <charconv>
#include <sstream>

namespace demcal::calibrate {
namespace {

std::string Number(double v) {
  char buffer[32];
  const auto r = std::to_chars(buffer, buffer + sizeof buffer, v);
  return std::string(buffer, r.ptr);
}

// "fix NAME all property/global KEY peratomtypepair N v11 v12 ... vNN" (row-major).
std::string PairLine(const std::string& fix, const std::string& key, const core::Scene& m,
                     double (*get)(const core::Scene&, const core::PairParameters&)) {
  const size_t n = m.materials.size();
  std::ostringstream out;
  out << "fix " << fix << " all property/global " << key << " peratomtypepair " << n;
  for (size_t k = 0; k < n * n; ++k) out << " " << Number(get(m, m.pair_parameters[k]));
  return out.str() + "\n";
}

}  // namespace

std::string LiggghtsMaterialInclude(const core::Scene& m, const std::vector<std::string>& comments) {
  std::ostringstream out;
  out << "# demcal parameters as LIGGGHTS-PUBLIC material settings (units si)\n";
  for (const std::string& c : comments) out << "# " << c << "\n";
  out << "# atom types:";
  for (size_t k = 0; k < m.materials.size(); ++k) out << " " << k + 1 << " = " << m.materials[k].name;
  out << "\n";
  const std::string& rolling = m.rolling.name;
  const std::string law = "model hertz tangential history" +
                          (rolling == "none" ? std::string() : " rolling_friction " + rolling);
  out << "# contact law: pair_style gran " << law << "\n"
      << "#              fix ... wall/gran " << law << " primitive type ...\n";
  out << "fix m1 all property/global youngsModulus peratomtype";
  for (const core::Material& mat : m.materials) out << " " << Number(mat.youngs_modulus_Pa);
  out << "\nfix m2 all property/global poissonsRatio peratomtype";
  for (const core::Material& mat : m.materials) out << " " << Number(mat.poisson_ratio);
  out << "\n";
  out << PairLine("m3", "coefficientRestitution", m, [](const core::Scene&, const core::PairParameters& p) { return p.restitution; });
  out << PairLine("m4", "coefficientFriction", m, [](const core::Scene&, const core::PairParameters& p) { return p.sliding_friction; });
  if (rolling != "none")
    out << PairLine("m5", "coefficientRollingFriction", m,
                    [](const core::Scene&, const core::PairParameters& p) { return p.rolling_friction; });
  if (rolling == "epsd")
    out << PairLine("m6", "coefficientRollingViscousDamping", m,
                    [](const core::Scene& s, const core::PairParameters&) { return s.rolling.epsd_damping_ratio; });
  bool adhesive = false;
  for (const core::PairParameters& p : m.pair_parameters) adhesive = adhesive || p.interfacial_energy_J_m2 > 0;
  if (adhesive) {
    out << "# interfacial energy Gamma (J/m2, EDEM convention, JKR work of adhesion 2*Gamma) per type pair,\n"
        << "# not representable in LIGGGHTS-PUBLIC (no JKR model):";
    for (const core::PairParameters& p : m.pair_parameters) out << " " << Number(p.interfacial_energy_J_m2);
    out << "\n";
  }
  return out.str();
}

}  // namespace demcal::calibrate
