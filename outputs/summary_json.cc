#include "outputs/summary_json.h"

#include "outputs/earlier_outputs.h"

#include <cmath>

#include "files/json_document.h"
#include "core/version.h"

namespace demcal::workflow {
namespace {
// JSON has no NaN or infinity: a non-finite figure (a blown-up run) is written as null.
nlohmann::ordered_json Finite(double v) {
  return std::isfinite(v) ? nlohmann::ordered_json(v) : nlohmann::ordered_json();
}
nlohmann::ordered_json FiniteVector(const core::Vec3& v) {
  return nlohmann::ordered_json::array({Finite(v.x), Finite(v.y), Finite(v.z)});
}
}  // namespace

nlohmann::ordered_json RunRecordToJson(const RunRecord& r) {
  const core::RunSummary& s = r.summary;
  nlohmann::ordered_json j;
  j["format"] = kRunSummaryFormat;
  j["demcal_version"] = kVersion;
  j["scene"] = r.scene_path;
  if (!r.scene_description.empty()) j["scene_description"] = r.scene_description;
  j["seed"] = r.seed ? nlohmann::ordered_json(*r.seed) : nlohmann::ordered_json();
  j["threads"] = r.threads_used;
  j["threads_requested"] = r.threads_requested;
  j["termination"] = core::TerminationName(s.termination);
  j["message"] = s.message;
  j["steps"] = s.steps;
  j["restarted_from"] = nlohmann::ordered_json();
  if (r.restarted_from) {
    j["restarted_from"]["checkpoint"] = r.restarted_from->checkpoint_path;
    j["restarted_from"]["time_s"] = Finite(r.restarted_from->time_s);
    j["restarted_from"]["steps"] = r.restarted_from->steps;
  }
  j["simulated_time_s"] = Finite(s.simulated_time_s);
  j["requested_duration_s"] =
      r.requested_duration_s ? Finite(*r.requested_duration_s) : nlohmann::ordered_json();
  j["timestep_s"] = Finite(s.timestep_s);
  j["particles"] = s.particles;
  j["final_kinetic_energy_J"] = Finite(s.final_kinetic_energy_J);
  j["neighbour_rebuilds"] = s.neighbour_rebuilds;
  j["wall_time_s"] = Finite(s.wall_time_s);
  j["phase_wall_time_s"] = {{"integrate_s", Finite(s.phases.integrate_s)},
                            {"insert_s", Finite(s.phases.insert_s)},
                            {"rebuild_check_s", Finite(s.phases.rebuild_check_s)},
                            {"rebuild_s", Finite(s.phases.rebuild_s)},
                            {"forces_s", Finite(s.phases.forces_s)},
                            {"checks_s", Finite(s.phases.checks_s)}};
  j["setup_wall_time_s"] = Finite(r.setup_wall_time_s);
  j["total_wall_time_s"] = Finite(r.total_wall_time_s);
  j["factories"] = nlohmann::ordered_json::array();
  for (const core::FactoryReport& f : r.factories) {
    nlohmann::ordered_json fj;
    fj["name"] = f.name;
    fj["particles"] = f.particles;
    fj["inserted_mass_kg"] = Finite(f.inserted_mass_kg);
    fj["requested_mass_kg"] = Finite(f.requested_mass_kg);
    fj["active_time_s"] = Finite(f.active_time_s);
    fj["requested_rate_kg_s"] = Finite(f.RequestedRate());
    fj["achieved_rate_kg_s"] = Finite(f.AchievedRate());
    fj["full_batches"] = f.full_batches;
    fj["region_lift_m"] = Finite(f.region_lift_m);
    j["factories"].push_back(fj);
  }
  j["factory_warnings"] = r.factory_warnings;
  j["sinks"] = nlohmann::ordered_json::array();
  for (const core::SinkReport& sink : r.sinks) {
    nlohmann::ordered_json sj;
    sj["name"] = sink.name;
    sj["removed_particles"] = sink.TotalParticles();
    sj["removed_mass_kg"] = Finite(sink.TotalMassKg());
    sj["last_removal_s"] = sink.last_removal_s >= 0 ? Finite(sink.last_removal_s) : nullptr;
    sj["per_species"] = nlohmann::ordered_json::array();
    for (size_t k = 0; k < sink.mass_kg.size() && k < r.species_names.size(); ++k)
      sj["per_species"].push_back({{"species", r.species_names[k]},
                                   {"removed_particles", sink.particles[k]},
                                   {"removed_mass_kg", Finite(sink.mass_kg[k])}});
    j["sinks"].push_back(sj);
  }
  j["wall_loads"] = nlohmann::ordered_json::array();
  for (const NamedWallLoad& w : r.wall_loads) {
    nlohmann::ordered_json wj;
    wj["name"] = w.name;
    wj["force_N"] = FiniteVector(w.load.force_N);
    wj["torque_N_m"] = FiniteVector(w.load.torque_N_m);
    wj["point_m"] = FiniteVector(w.load.point_m);
    j["wall_loads"].push_back(wj);
  }
  j["output_error"] =
      r.output_error.empty() ? nlohmann::ordered_json() : nlohmann::ordered_json(r.output_error);
  j["outputs"] = r.outputs;
  if (!r.earlier_outputs_moved.empty()) {
    j["earlier_outputs_moved_to"] = std::string(kPreviousRunDir) + "/";
    j["earlier_outputs_moved"] = r.earlier_outputs_moved;
  }
  return j;
}

bool WriteRunSummaryJson(const std::string& path, const RunRecord& record, std::string* error) {
  return WriteJsonFile(path, RunRecordToJson(record), error);
}

}  // namespace demcal::workflow
