#include "objectives/report/discharge_csv.h"

#include <limits>

#include "objectives/report/text_file.h"

namespace demcal::objectives {

namespace {

void Header(std::ostream& out, const std::string& prefix,
            const std::vector<std::string>& species_names, const std::string& suffix) {
  for (const std::string& name : species_names) out << "," << prefix << name << suffix;
  out << "\n";
}

}  // namespace

void WriteOutflowCsv(std::ostream& out, const std::vector<OutflowSample>& samples,
                     const std::vector<std::string>& species_names) {
  out.precision(std::numeric_limits<double>::max_digits10);
  out << "time_s";
  Header(out, "mass_", species_names, "_kg");
  for (const OutflowSample& s : samples) {
    out << s.time_s;
    for (double m : s.cumulative_mass_kg) out << "," << m;
    out << "\n";
  }
}

bool WriteOutflowCsv(const std::string& path, const std::vector<OutflowSample>& samples,
                     const std::vector<std::string>& species_names, std::string* error) {
  return WriteTextFile(
      path, [&](std::ostream& out) { WriteOutflowCsv(out, samples, species_names); }, error);
}

void WriteCompositionCsv(std::ostream& out, const std::vector<CompositionBin>& bins,
                         const std::vector<std::string>& species_names) {
  out.precision(std::numeric_limits<double>::max_digits10);
  out << "t_start_s,t_end_s,mass_kg";
  Header(out, "fraction_", species_names, "");
  for (const CompositionBin& b : bins) {
    out << b.t_start_s << "," << b.t_end_s << "," << b.mass_kg;
    for (double f : b.mass_fraction) out << "," << f;
    out << "\n";
  }
}

bool WriteCompositionCsv(const std::string& path, const std::vector<CompositionBin>& bins,
                         const std::vector<std::string>& species_names, std::string* error) {
  return WriteTextFile(
      path, [&](std::ostream& out) { WriteCompositionCsv(out, bins, species_names); }, error);
}

}  // namespace demcal::objectives
