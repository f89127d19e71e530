#include "calibrate/liggghts_export.h"

#include <charconv>
#include <cmath>
#include <numbers>
#include <sstream>

namespace demcal::calibrate {
namespace {

std::string Number(double v) {
  char buffer[32];
  const auto r = std::to_chars(buffer, buffer + sizeof buffer, v);
  return std::string(buffer, r.ptr);
}

// Number-mean diameter of a size distribution (m).
double MeanDiameter(const core::SizeDistribution& s) {
  using Kind = core::SizeDistribution::Kind;
  if (s.kind == Kind::kFixed) return s.diameter_m;
  if (s.kind == Kind::kUniform) return 0.5 * (s.min_diameter_m + s.max_diameter_m);
  double sum = 0;
  for (size_t k = 0; k < s.table_diameter_m.size(); ++k)
    sum += s.table_diameter_m[k] * s.table_number_fraction[k];
  return sum;
}

double EffectiveYoungs(const core::Material& a, const core::Material& b) {
  return 1.0 / ((1 - a.poisson_ratio * a.poisson_ratio) / a.youngs_modulus_Pa +
                (1 - b.poisson_ratio * b.poisson_ratio) / b.youngs_modulus_Pa);
}

std::string PairName(const core::Scene& m, size_t i, size_t j) {
  return "material pair " + m.materials[i].name + "–" + m.materials[j].name;
}

// "fix NAME all property/global KEY peratomtypepair N v11 v12 ... vNN" (row-major).
std::string PairLine(const std::string& fix, const std::string& key, size_t n,
                     const std::vector<double>& values) {
  std::ostringstream out;
  out << "fix " << fix << " all property/global " << key << " peratomtypepair " << n;
  for (double v : values) out << " " << Number(v);
  return out.str() + "\n";
}

template <class Get>
std::vector<double> PairValues(const core::Scene& m, Get get) {
  std::vector<double> v;
  for (const core::PairParameters& p : m.pair_parameters) v.push_back(get(p));
  return v;
}

// The conversion of pair (i, j)'s rolling coefficient; false with *error when refused.
bool RollingFactor(const core::Scene& m, const ContactUse& use, const LiggghtsLawOptions& options,
                   size_t i, size_t j, double* factor, std::string* error) {
  *factor = 1;
  if (m.rolling.name != "cdt" ||
      m.pair_parameters[i * m.materials.size() + j].rolling_friction == 0)
    return true;
  const double ri = use.mean_radius_m[i], rj = use.mean_radius_m[j];
  const bool grains = ri > 0 && rj > 0;
  const bool wall = (ri > 0 && use.wall[j]) || (rj > 0 && use.wall[i]);
  if (!grains && !wall) return true;  // no contact of the model uses this pair
  const std::string law =
      "demcal's rolling law cdt (EDEM: μr·Fn·R_i against each grain's own spin) is not "
      "LIGGGHTS' cdt (μr·Fn·R* against the relative spin)";
  if (!options.cdt_torque_conversion) {
    *error = PairName(m, i, j) + ": " + law + "; the torque conversion does not reproduce a " +
             "heap (docs/export.md); pass --rolling-conversion torque to export it anyway, or " +
             "calibrate with epsd2, which both codes share";
    return false;
  }
  if (grains && wall) {
    *error = PairName(m, i, j) + ": " + law + "; the pair meets both grain–grain and " +
             "grain–wall contacts, whose converted coefficients differ (×" +
             Number(CdtParticleFactor(ri, rj)) + " and ×1) and LIGGGHTS holds one per type pair";
    return false;
  }
  *factor = grains ? CdtParticleFactor(ri, rj) : 1.0;
  return true;
}

}  // namespace

double CdtParticleFactor(double radius_i_m, double radius_j_m) {
  const double s = radius_i_m + radius_j_m;
  return s * s / (2 * radius_i_m * radius_j_m);
}

double SjkrEnergyDensity(double gamma_J_m2, double effective_youngs_Pa, double effective_radius_m) {
  const double pi = std::numbers::pi;
  const double pull_off_N = 3 * pi * gamma_J_m2 * effective_radius_m;
  const double a0_cubed =
      9 * pi * gamma_J_m2 * effective_radius_m * effective_radius_m / effective_youngs_Pa;
  const double a0 = std::cbrt(a0_cubed);
  return pull_off_N / (pi * a0 * a0);
}

ContactUse ContactUseOf(const core::Scene& model, const std::vector<int>& wall_materials) {
  const size_t n = model.materials.size();
  ContactUse use{std::vector<double>(n, 0), std::vector<bool>(n, false)};
  std::vector<int> count(n, 0);
  for (const core::Species& s : model.species) {
    if (s.material < 0 || s.material >= static_cast<int>(n)) continue;
    use.mean_radius_m[s.material] += 0.5 * MeanDiameter(s.size);
    ++count[s.material];
  }
  for (size_t k = 0; k < n; ++k)
    if (count[k] > 0) use.mean_radius_m[k] /= count[k];
  for (int w : wall_materials)
    if (w >= 0 && w < static_cast<int>(n)) use.wall[w] = true;
  return use;
}

ContactUse ContactUseOf(const core::Scene& model) {
  std::vector<int> walls;
  ContactUse use = ContactUseOf(model, walls);
  for (size_t k = 0; k < model.materials.size(); ++k)
    if (use.mean_radius_m[k] == 0) walls.push_back(static_cast<int>(k));
  return ContactUseOf(model, walls);
}

bool ConvertToLiggghts(const core::Scene& m, const ContactUse& use,
                       const LiggghtsLawOptions& options, LiggghtsLaw* law, std::string* error) {
  const std::string& rolling = m.rolling.name;
  if (rolling != "none" && rolling != "cdt" && rolling != "cdt_relative" && rolling != "epsd" &&
      rolling != "epsd2") {
    *error = "rolling law '" + rolling + "' has no LIGGGHTS-PUBLIC counterpart";
    return false;
  }
  const size_t n = m.materials.size();
  *law = {};
  // cdt_relative is LIGGGHTS' own cdt law (same lever R*, same relative rotation), so its
  // coefficient goes across unchanged; demcal's "cdt" is EDEM's law (RollingFactor).
  const std::string liggghts_rolling = rolling == "cdt_relative" ? "cdt" : rolling;
  const std::string rolling_part =
      rolling == "none" ? "" : " rolling_friction " + liggghts_rolling;
  law->model = "model hertz tangential history" + rolling_part;
  bool adhesive = false;
  for (size_t i = 0; i < n; ++i) {
    for (size_t j = 0; j < n; ++j) {
      const core::PairParameters& p = m.pair_parameters[i * n + j];
      double factor = 1;
      if (!RollingFactor(m, use, options, i, j, &factor, error)) return false;
      law->rolling_coefficient.push_back(p.rolling_friction * factor);
      if (factor != 1 && i <= j)
        law->notes.push_back(PairName(m, i, j) + ": cdt μr " + Number(p.rolling_friction) +
                             " written as " + Number(p.rolling_friction * factor) +
                             " (torque conversion ×" + Number(factor) + ")");
      adhesive = adhesive || p.interfacial_energy_J_m2 > 0 || p.cohesion_energy_density_J_m3 > 0;
    }
  }
  if (!adhesive) return true;
  for (size_t i = 0; i < n; ++i) {
    for (size_t j = 0; j < n; ++j) {
      const double gamma = m.pair_parameters[i * n + j].interfacial_energy_J_m2;
      // A pair with sjkr's own k goes across as it is: the same law (core/contact/sjkr.h).
      double k = m.pair_parameters[i * n + j].cohesion_energy_density_J_m3;
      if (gamma > 0) {
        if (!options.sjkr_approximation) {
          *error = PairName(m, i, j) + ": JKR adhesion (Γ = " + Number(gamma) +
                   " J/m²) has no LIGGGHTS-PUBLIC counterpart (its sjkr is another law); pass " +
                   "--cohesion-approximation sjkr to export it as sjkr (docs/export.md)";
          return false;
        }
        const double ri = use.mean_radius_m[i], rj = use.mean_radius_m[j];
        const double r = ri > 0 && rj > 0 ? ri * rj / (ri + rj) : std::max(ri, rj);
        if (r > 0) k = SjkrEnergyDensity(gamma, EffectiveYoungs(m.materials[i], m.materials[j]), r);
        if (i <= j && r > 0)
          law->notes.push_back(PairName(m, i, j) + ": JKR Γ " + Number(gamma) +
                               " J/m² written as sjkr k " + Number(k) + " J/m³ (R* " + Number(r) +
                               " m; another law, docs/export.md)");
      }
      law->cohesion_energy_density_J_m3.push_back(k);
    }
  }
  // fix wall/gran and pair gran want model, tangential, cohesion, rolling_friction in this order.
  law->model = "model hertz tangential history cohesion sjkr" + rolling_part;
  return true;
}

std::string LiggghtsMaterialLines(const core::Scene& m, const LiggghtsLaw& law) {
  const size_t n = m.materials.size();
  std::ostringstream out;
  out << "fix m1 all property/global youngsModulus peratomtype";
  for (const core::Material& mat : m.materials) out << " " << Number(mat.youngs_modulus_Pa);
  out << "\nfix m2 all property/global poissonsRatio peratomtype";
  for (const core::Material& mat : m.materials) out << " " << Number(mat.poisson_ratio);
  out << "\n";
  out << PairLine("m3", "coefficientRestitution", n,
                  PairValues(m, [](const core::PairParameters& p) { return p.restitution; }));
  out << PairLine("m4", "coefficientFriction", n,
                  PairValues(m, [](const core::PairParameters& p) { return p.sliding_friction; }));
  if (m.rolling.name != "none")
    out << PairLine("m5", "coefficientRollingFriction", n, law.rolling_coefficient);
  if (m.rolling.name == "epsd")
    out << PairLine("m6", "coefficientRollingViscousDamping", n,
                    std::vector<double>(n * n, m.rolling.epsd_damping_ratio));
  if (!law.cohesion_energy_density_J_m3.empty())
    out << PairLine("m7", "cohesionEnergyDensity", n, law.cohesion_energy_density_J_m3);
  return out.str();
}

std::string LiggghtsMaterialInclude(const core::Scene& m,
                                    const std::vector<std::string>& comments) {
  std::ostringstream out;
  out << "# demcal parameters as LIGGGHTS-PUBLIC 3.8 material settings (units si)\n";
  for (const std::string& c : comments) out << "# " << c << "\n";
  out << "# atom types:";
  for (size_t k = 0; k < m.materials.size(); ++k)
    out << " " << k + 1 << " = " << m.materials[k].name;
  out << "\n";
  LiggghtsLaw law;
  std::string error;
  if (!ConvertToLiggghts(m, ContactUseOf(m), {}, &law, &error)) {
    out << "# NOT EXPORTED: " << error << "\n";
    return out.str();
  }
  for (const std::string& note : law.notes) out << "# " << note << "\n";
  out << "# contact law: pair_style gran " << law.model << "\n"
      << "#              fix ... wall/gran " << law.model << " primitive type ...\n";
  return out.str() + LiggghtsMaterialLines(m, law);
}

}  // namespace demcal::calibrate
