#include "workflow/export/liggghts_deck.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <sstream>

#include "core/version.h"
#include "files/json_document.h"
#include "objectives/report/text_file.h"
#include "outputs/exit_codes.h"
#include "workflow/export/liggghts_insertion.h"
#include "workflow/export/liggghts_number.h"
#include "workflow/export/liggghts_walls.h"

namespace demcal::workflow {
namespace {

int64_t Steps(double time_s, double dt) { return std::max<int64_t>(0, std::llround(time_s / dt)); }

// "run" lines from `from_s` to `to_s` with the removals that fall between, in time order.
void RunTo(double* now_s, double to_s, double dt, std::multimap<double, std::string>* events,
           std::ostream& out) {
  while (!events->empty() && events->begin()->first <= to_s) {
    const auto e = events->begin();
    if (Steps(e->first, dt) > Steps(*now_s, dt))
      out << "run " << Steps(e->first, dt) - Steps(*now_s, dt) << "\n";
    *now_s = std::max(*now_s, e->first);
    out << "unfix " << e->second << "   # removed at " << Num(e->first) << " s\n";
    events->erase(e);
  }
  if (Steps(to_s, dt) > Steps(*now_s, dt))
    out << "run " << Steps(to_s, dt) - Steps(*now_s, dt) << "\n";
  *now_s = std::max(*now_s, to_s);
}

std::string Header(const core::Scene& s, const LiggghtsParticles& particles) {
  std::ostringstream out;
  const char* p[2] = {"f", "p"};
  out << "units si\natom_style granular\natom_modify map array\nboundary " << p[s.periodic[0]]
      << " " << p[s.periodic[1]] << " " << p[s.periodic[2]]
      << "\nnewton off\ncommunicate single vel yes\n";
  if (!particles.data_file.empty()) {
    out << "read_data particles.data\n";
  } else {
    out << "region domain block " << Num(s.domain_min_m.x) << " " << Num(s.domain_max_m.x) << " "
        << Num(s.domain_min_m.y) << " " << Num(s.domain_max_m.y) << " " << Num(s.domain_min_m.z)
        << " " << Num(s.domain_max_m.z) << " units box\ncreate_box " << s.materials.size()
        << " domain\n";
  }
  out << "neighbor " << Num(core::NeighbourSkin(s)) << " bin\nneigh_modify delay 0\n";
  return out.str();
}

std::string Groups(const core::Scene& s, const LiggghtsParticles& particles) {
  std::ostringstream out;
  if (particles.fixed > 0) {
    out << "group fixed id 1:" << particles.fixed << "\ngroup flow subtract all fixed\n"
        << "neigh_modify exclude group fixed fixed\n";
  } else {
    out << "group flow type";
    for (size_t k = 0; k < s.materials.size(); ++k) out << " " << k + 1;
    out << "\n";
  }
  return out.str();
}

// LIGGGHTS refuses Young's moduli outside [5 MPa, 1 GPa] in SI units unless told: reduced
// stiffness fidelities go below, real Perspex or steel above.
std::string StiffnessRange(const core::Scene& s) {
  bool soft = false, hard = false;
  for (const core::Material& m : s.materials) {
    soft = soft || m.youngs_modulus_Pa < 5e6;
    hard = hard || m.youngs_modulus_Pa > 1e9;
  }
  return std::string(soft ? "soft_particles yes\n" : "") + (hard ? "hard_particles yes\n" : "");
}

// A loop of at most `max_runs` runs of `every` steps that ends early once `condition` holds:
// LIGGGHTS' `if ... then "jump SELF <label>_done"` out of a `variable <label> loop`.
void LoopUntil(const std::string& label, int64_t max_runs, int64_t every,
               const std::string& condition, std::ostream& out) {
  if (max_runs <= 0) return;
  out << "variable " << label << " loop " << max_runs << "\nlabel " << label << "_next\nrun "
      << std::max<int64_t>(1, every) << "\nif \"" << condition << "\" then \"jump SELF " << label
      << "_done\"\nnext " << label << "\njump SELF " << label << "_next\nlabel " << label
      << "_done\n";
}

// The runs: to a settled state or a set time or the scene's duration, then (with a wall to
// take away) the opening and the run until nothing is left above the given height.
bool RunSection(const ExportRun& run, const LiggghtsWallSet& walls, double dt, std::ostream& out,
                std::string* error) {
  std::multimap<double, std::string> events(walls.removals.begin(), walls.removals.end());
  double now = 0;
  const objectives::SettleCriteria& c = run.settle_criteria;
  const int64_t check_steps = Steps(c.check_interval_s, dt);
  if (run.settle) {
    const double first = std::min(c.feed_end_s + c.min_settle_s, c.max_time_s);
    out << "# settle: until the moving grains' specific kinetic energy is below "
        << Num(c.specific_kinetic_J_kg) << " J/kg, checked every " << Num(c.check_interval_s)
        << " s, or " << Num(c.max_time_s) << " s\n";
    RunTo(&now, first, dt, &events, out);
    LoopUntil("settle",
              static_cast<int64_t>(std::ceil((c.max_time_s - first) / c.check_interval_s)),
              check_steps, "${specific_ke} < " + Num(c.specific_kinetic_J_kg), out);
  } else {
    RunTo(&now, run.open_wall.empty() ? run.scene.time.duration_s : run.open_at_s, dt, &events,
          out);
  }
  if (run.open_wall.empty()) return true;
  std::string ids;
  for (size_t k = 0; k < run.scene.walls.size(); ++k)
    if (run.scene.walls[k].name == run.open_wall) ids = walls.fix_ids[k];
  if (ids.empty()) {
    *error = "no wall named '" + run.open_wall + "' to open";
    return false;
  }
  out << "\n# open: wall '" << run.open_wall
      << "' taken away; then until no grain is above z = " << Num(run.empty_above_z_m) << " m, or "
      << Num(run.after_open_max_s) << " s\nunfix " << ids << "\n";
  LoopUntil("discharge", static_cast<int64_t>(std::ceil(run.after_open_max_s / c.check_interval_s)),
            check_steps, "${left} == 0", out);
  return true;
}

}  // namespace

bool LiggghtsDeck(const ExportRun& run, const ExportOptions& options,
                  const std::vector<std::string>& comments, std::string* deck,
                  std::vector<std::pair<std::string, std::string>>* files,
                  nlohmann::ordered_json* summary, std::string* error) {
  const core::Scene& s = run.scene;
  if (!s.sinks.empty()) {
    *error = "sink '" + s.sinks.front().name + "' is not exported (LIGGGHTS removes grains " +
             "only where they leave the domain)";
    return false;
  }
  const double dt = core::TimeStep(s);
  LiggghtsWallSet walls;
  calibrate::LiggghtsLaw law;
  LiggghtsParticles particles;
  // The walls are read first for their materials, which the rolling conversion needs.
  if (!LiggghtsWalls(s, "", &walls, error) ||
      !calibrate::ConvertToLiggghts(s, calibrate::ContactUseOf(s, walls.materials), options.law,
                                    &law, error) ||
      !LiggghtsWalls(s, law.model, &walls, error) ||
      !LiggghtsParticleCommands(s, dt, &particles, error))
    return false;
  std::ostringstream out;
  out << "# LIGGGHTS-PUBLIC 3.8 deck written by demcal " << kVersion
      << " (demcal export liggghts; docs/export.md). Run in this folder: liggghts -in in.demcal\n";
  for (const std::string& c : comments) out << "# " << c << "\n";
  out << "# atom types:";
  for (size_t k = 0; k < s.materials.size(); ++k)
    out << " " << k + 1 << " = " << s.materials[k].name;
  out << "\n";
  for (const std::string& n : law.notes) out << "# " << n << "\n";
  out << "\n"
      << Header(s, particles) << "\n# materials and pairs (SI)\n"
      << StiffnessRange(s) << calibrate::LiggghtsMaterialLines(s, law) << "pair_style gran "
      << law.model << "\npair_coeff * *\ntimestep " << Num(dt) << "\nfix gravity all gravity "
      << Num(Norm(s.gravity_m_s2)) << " vector " << Num(s.gravity_m_s2.x) << " "
      << Num(s.gravity_m_s2.y) << " " << Num(s.gravity_m_s2.z) << "\n\n"
      << Groups(s, particles) << "\n# walls\n"
      << walls.commands << "\n# particles\n"
      << particles.commands << "\n# integration: only group flow moves\n";
  // fix multisphere integrates the clumps; nve/sphere would move their member spheres again.
  out << (particles.clumps ? "fix integrate flow multisphere allow_group_and_set yes\n"
                           : "fix integrate flow nve/sphere\n");
  const int64_t dump_every = std::max<int64_t>(1, Steps(options.dump_interval_s, dt));
  const double check_s = run.settle || !run.open_wall.empty() ? run.settle_criteria.check_interval_s
                                                              : options.dump_interval_s;
  out << "\n# outputs\ncompute ke flow ke\n"
      << "compute rke flow erotate/sphere\n"
      << "variable specific_ke equal (c_ke+c_rke)/(mass(flow)+1e-300)   # J/kg\n"
      << "variable time equal step*dt   # s\n"
      << (run.open_wall.empty()
              ? std::string()
              : "region above block INF INF INF INF " + Num(run.empty_above_z_m) +
                    " INF units box\nvariable left equal count(flow,above)\n"
                    "variable mass_above equal mass(flow,above)   # kg, the outflow's complement\n")
      << "thermo_style custom step v_time atoms v_specific_ke"
      << (run.open_wall.empty() ? "" : " v_mass_above") << " cpu\nthermo "
      << std::max<int64_t>(1, Steps(check_s, dt)) << "\nthermo_modify lost ignore norm no\n"
      << "dump particles all custom " << dump_every
      << " post/dump_*.liggghts id type x y z vx vy vz omegax omegay omegaz radius mass\n\n";
  if (!RunSection(run, walls, dt, out, error)) return false;
  out << "write_dump all custom post/final.liggghts id type x y z vx vy vz radius mass\n"
      << "print \"demcal export: run finished\"\n";
  *deck = out.str();
  files->clear();
  if (!particles.data_file.empty()) files->emplace_back("particles.data", particles.data_file);
  for (const auto& f : walls.stl_files) files->push_back(f);
  const objectives::SettleCriteria& c = run.settle_criteria;
  nlohmann::ordered_json j;
  j["timestep_s"] = dt;
  j["contact_law"] = law.model;
  j["conversions"] = law.notes;
  j["placed_particles"] = particles.placed;
  j["fixed_particles"] = particles.fixed;
  j["base_top_m"] = run.base_top_m;
  if (run.settle)
    j["settle"] = {{"feed_end_s", c.feed_end_s},
                   {"min_settle_s", c.min_settle_s},
                   {"specific_kinetic_J_kg", c.specific_kinetic_J_kg},
                   {"check_interval_s", c.check_interval_s},
                   {"max_time_s", c.max_time_s}};
  else if (run.open_wall.empty())
    j["duration_s"] = s.time.duration_s;
  if (!run.open_wall.empty())
    j["opening"] = {{"wall", run.open_wall},
                    {"at_s", run.open_at_s > 0 ? nlohmann::ordered_json(run.open_at_s)
                                               : nlohmann::ordered_json("settled")},
                    {"max_after_s", run.after_open_max_s},
                    {"until_none_above_z_m", run.empty_above_z_m}};
  j["dump_interval_s"] = dump_every * dt;
  *summary = j;
  return true;
}

}  // namespace demcal::workflow
