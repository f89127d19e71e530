#include "outputs/mass_flow_log.h"

#include <cmath>
#include <iomanip>
#include <sstream>

#include "core/io/atomic_file.h"
#include "core/io/input_file.h"

namespace demcal::workflow {
namespace {

// The log is rewritten whole at each record, so it is held in memory anyway; 1 GiB is millions
// of rows, far beyond any run's.
constexpr size_t kMaxLogBytes = size_t{1} << 30;

}  // namespace

MassFlowLog::MassFlowLog(std::string path, const OutputSettings& settings)
    : path_(std::move(path)),
      interval_s_(settings.mass_flow_interval_s),
      planes_(settings.mass_flow_planes) {}

int64_t MassFlowLog::EverySteps(double timestep_s) const {
  if (!(interval_s_ > 0) || !(timestep_s > 0)) return 0;
  return std::max<int64_t>(1, std::llround(interval_s_ / timestep_s));
}

std::string MassFlowLog::Header(const core::Simulation& sim) const {
  const std::vector<core::Species>& species = sim.scene().species;
  std::ostringstream os;
  os << "time_s";
  for (const core::SinkReport& r : sim.SinkReports())
    for (const core::Species& s : species)
      os << ",sink." << r.name << "." << s.name << ".removed_count,sink." << r.name << "."
         << s.name << ".removed_mass_kg";
  for (const core::SinkSpec& plane : planes_)
    for (const core::Species& s : species)
      os << ",plane." << plane.name << "." << s.name << ".mass_beyond_kg";
  for (const core::FactoryReport& f : sim.FactoryReports())
    os << ",factory." << f.name << ".inserted_mass_kg";
  return os.str();
}

std::vector<double> MassFlowLog::Row(const core::Simulation& sim) const {
  std::vector<double> row{sim.time_s()};
  for (const core::SinkReport& r : sim.SinkReports())
    for (size_t k = 0; k < r.mass_kg.size(); ++k) {
      row.push_back(static_cast<double>(r.particles[k]));
      row.push_back(r.mass_kg[k]);
    }
  const size_t n_species = sim.scene().species.size();
  std::vector<double> beyond(planes_.size() * n_species, 0.0);
  const core::Particles& p = sim.particles();
  const core::Clumps& clumps = sim.system().clumps;
  for (size_t i = 0; i < p.Size(); ++i) {
    if (p.body[i] >= 0) continue;  // clumps below, by their centre of mass
    for (size_t k = 0; k < planes_.size(); ++k)
      if (planes_[k].Contains(p.position_m[i])) beyond[k * n_species + p.species[i]] += p.mass_kg[i];
  }
  for (size_t c = 0; c < clumps.Size(); ++c)
    for (size_t k = 0; k < planes_.size(); ++k)
      if (planes_[k].Contains(clumps.position_m[c]))
        beyond[k * n_species + clumps.species[c]] += clumps.mass_kg[c];
  row.insert(row.end(), beyond.begin(), beyond.end());
  for (const core::FactoryReport& f : sim.FactoryReports()) row.push_back(f.inserted_mass_kg);
  return row;
}

bool MassFlowLog::ResumeFrom(const core::Simulation& sim, std::string* error) {
  // A FIFO or device at the log's name is refused rather than read (which would block or never
  // end); a missing log is nothing to continue.
  std::string text;
  if (!core::io::ReadRegularFile(path_, "mass flow log", kMaxLogBytes, {.missing_is_empty = true},
                                 &text, error)) {
    if (error) *error = "cannot continue: " + *error;
    return false;
  }
  std::istringstream in(std::move(text));
  std::string line;
  if (!std::getline(in, line)) {  // nothing to continue
    Record(sim);
    return true;
  }
  if (line != Header(sim)) {
    if (error) *error = "cannot continue '" + path_ + "': its columns differ from this scene's";
    return false;
  }
  while (std::getline(in, line)) {
    std::vector<double> row;
    std::istringstream fields(line);
    std::string field;
    while (std::getline(fields, field, ',')) row.push_back(std::strtod(field.c_str(), nullptr));
    if (row.empty() || row[0] > sim.time_s()) break;
    rows_.push_back(std::move(row));
  }
  Record(sim);
  return true;
}

void MassFlowLog::Record(const core::Simulation& sim) {
  if (!enabled() || (!rows_.empty() && rows_.back()[0] == sim.time_s())) return;
  rows_.push_back(Row(sim));
}

bool MassFlowLog::Flush(const core::Simulation& sim, std::string* error) const {
  if (!enabled()) return true;
  const std::string header = Header(sim);
  return core::io::WriteFileAtomically(
      path_,
      [&](std::ostream& out) {
        out << header << "\n" << std::setprecision(17);
        for (const std::vector<double>& row : rows_) {
          for (size_t k = 0; k < row.size(); ++k) out << (k ? "," : "") << row[k];
          out << "\n";
        }
      },
      error);
}

}  // namespace demcal::workflow
