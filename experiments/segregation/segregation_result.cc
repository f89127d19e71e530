#include "experiments/segregation/segregation_result.h"

#include <functional>

#include "experiments/segregation/mechanism/mechanism_observables.h"
#include "objectives/common/replicates.h"

namespace demcal::workflow {

namespace {

using nlohmann::ordered_json;
using objectives::HeapSegregation;
using objectives::SegregationIndex;
using objectives::SegregationRun;

// One index of one species, from a run's analysis; nullptr when the run has none.
using IndexOf = std::function<const SegregationIndex*(const HeapSegregation&, int species)>;

ordered_json StatJson(const objectives::Summary& s) {
  return {{"mean", s.n > 0 ? ordered_json(s.mean) : ordered_json(nullptr)},
          {"sem", s.n > 1 ? ordered_json(s.sem) : ordered_json(nullptr)},
          {"n", s.n}};
}

ordered_json FloorJson(const FloorEstimate& f) {
  auto value = [&f](double v) { return f.n > 0 ? ordered_json(v) : ordered_json(nullptr); };
  return {{"mean", value(f.mean)}, {"low", value(f.low)}, {"high", value(f.high)}, {"n", f.n}};
}

// Mean ± sem over the ok runs of value(index) for the defined indices.
objectives::Summary IndexStat(const std::vector<SegregationRun>& runs, int species,
                              const IndexOf& of, double SegregationIndex::*value) {
  std::vector<double> values;
  for (const SegregationRun& run : runs) {
    if (!run.ok()) continue;
    const SegregationIndex* index = of(run.analysis->indices, species);
    if (index && index->defined) values.push_back(index->*value);
  }
  return objectives::Summarise(values);
}

// The random-mixture floor of one index of one species, from a run's floor; nullptr without.
using FloorOf = std::function<const objectives::IndexFloor*(const objectives::HeapFloor&, int)>;

// Mean over the ok runs of the floor's mean, low and high band edge (of CoV or of S_n).
FloorEstimate FloorStat(const std::vector<SegregationRun>& runs, int species, const FloorOf& of,
                       bool s_n) {
  std::vector<double> mean, low, high;
  for (const SegregationRun& run : runs) {
    if (!run.ok() || !run.floor) continue;
    const objectives::IndexFloor* f = of(*run.floor, species);
    if (!f || !(s_n ? f->s_n_defined : f->defined)) continue;
    mean.push_back(s_n ? f->s_n_mean : f->cov_mean);
    low.push_back(s_n ? f->s_n_low : f->cov_low);
    high.push_back(s_n ? f->s_n_high : f->cov_high);
  }
  auto average = [](const std::vector<double>& v) {
    return v.empty() ? 0.0 : objectives::Summarise(v).mean;
  };
  return {average(mean), average(low), average(high), mean.size()};
}

const objectives::IndexFloor* FloorNumber(const objectives::RegionFloor& region, int species) {
  return species < static_cast<int>(region.species.size()) ? &region.species[species].number
                                                           : nullptr;
}
const objectives::IndexFloor* FloorMass(const objectives::RegionFloor& region, int species) {
  return species < static_cast<int>(region.species.size()) ? &region.species[species].mass
                                                           : nullptr;
}

// The floors beside the indices of one region: cov_<region>_floor, s_n_<region>_floor.
void AddFloor(const std::vector<SegregationRun>& runs, int k, const std::string& region,
              const FloorOf& of, SegregationSpeciesResult* out) {
  out->floors.emplace_back("cov_" + region + "_floor", FloorStat(runs, k, of, false));
  out->floors.emplace_back("s_n_" + region + "_floor", FloorStat(runs, k, of, true));
}

const SegregationIndex* Number(const objectives::RegionSegregation& region, int species) {
  return species < static_cast<int>(region.species.size()) ? &region.species[species].number
                                                           : nullptr;
}
const SegregationIndex* Mass(const objectives::RegionSegregation& region, int species) {
  return species < static_cast<int>(region.species.size()) ? &region.species[species].mass
                                                           : nullptr;
}

SegregationSpeciesResult SpeciesResult(const std::vector<SegregationRun>& runs, int k,
                                       const std::string& name, int layers) {
  const IndexOf front = [](const HeapSegregation& h, int s) { return Number(h.front, s); };
  const IndexOf back = [](const HeapSegregation& h, int s) { return Number(h.back, s); };
  const IndexOf whole = [](const HeapSegregation& h, int s) { return Mass(h.whole, s); };
  SegregationSpeciesResult out;
  out.species = name;
  auto add = [&](const char* index, const IndexOf& of, double SegregationIndex::*value) {
    out.indices.push_back({index, IndexStat(runs, k, of, value)});
  };
  add("cov_2d_front", front, &SegregationIndex::cov_m);
  add("cov_r_2d_front", front, &SegregationIndex::cov_r);
  add("s_n_2d_front", front, &SegregationIndex::s_n);
  add("cov_2d_back", back, &SegregationIndex::cov_m);
  add("cov_r_2d_back", back, &SegregationIndex::cov_r);
  add("s_n_2d_back", back, &SegregationIndex::s_n);
  add("cov_3d", whole, &SegregationIndex::cov_m);
  add("cov_r_3d", whole, &SegregationIndex::cov_r);
  add("s_n_3d", whole, &SegregationIndex::s_n);
  add("mean_mass_fraction_3d", whole, &SegregationIndex::mean_fraction);
  std::vector<double> outflow;  // of all that left the funnel (Fig. 16's average level)
  for (const SegregationRun& run : runs)
    if (run.ok() && k < static_cast<int>(run.outflow_mass_fraction.size()))
      outflow.push_back(run.outflow_mass_fraction[k]);
  out.indices.push_back({"outflow_mass_fraction", objectives::Summarise(outflow)});
  using objectives::HeapFloor;
  AddFloor(
      runs, k, "2d_front", [](const HeapFloor& f, int s) { return FloorNumber(f.front, s); }, &out);
  AddFloor(
      runs, k, "2d_back", [](const HeapFloor& f, int s) { return FloorNumber(f.back, s); }, &out);
  AddFloor(
      runs, k, "3d", [](const HeapFloor& f, int s) { return FloorMass(f.whole, s); }, &out);
  for (int layer = 0; layer < layers; ++layer) {
    const IndexOf of = [layer](const HeapSegregation& h, int s) -> const SegregationIndex* {
      return layer < static_cast<int>(h.layers.size()) ? Mass(h.layers[layer], s) : nullptr;
    };
    LayerEstimate l;
    l.cov = IndexStat(runs, k, of, &SegregationIndex::cov_m);
    l.floor = FloorStat(
        runs, k,
        [layer](const objectives::HeapFloor& f, int s) -> const objectives::IndexFloor* {
          return layer < static_cast<int>(f.layers.size()) ? FloorMass(f.layers[layer], s)
                                                           : nullptr;
        },
        false);
    out.cov_per_layer_3d.push_back(l);
  }
  return out;
}

ordered_json SpeciesJson(const SegregationSpeciesResult& s) {
  ordered_json j;
  j["species"] = s.species;
  for (const NamedEstimate& index : s.indices) j[index.name] = StatJson(index.value);
  for (const auto& [name, floor] : s.floors) j[name] = FloorJson(floor);
  ordered_json per_layer = ordered_json::array();
  for (size_t layer = 0; layer < s.cov_per_layer_3d.size(); ++layer) {
    ordered_json l = StatJson(s.cov_per_layer_3d[layer].cov);
    l["layer"] = layer + 1;
    l["floor"] = FloorJson(s.cov_per_layer_3d[layer].floor);
    per_layer.push_back(l);
  }
  j["cov_per_layer_3d"] = per_layer;
  return j;
}

ordered_json TrackedJson(const objectives::TrackedGranule& g) {
  ordered_json j;
  j["id"] = g.track.id;
  j["samples"] = g.track.samples.size();
  j["impact_time_s"] = g.impact_sample ? ordered_json(g.impact_time_s) : nullptr;
  j["peak_specific_kinetic_J_kg"] =
      g.impact_sample ? ordered_json(g.peak_specific_kinetic_J_kg) : nullptr;
  j["penetration_depth_m"] = g.penetration ? ordered_json(g.penetration->depth_m) : nullptr;
  j["penetration_depth_diameters"] =
      g.penetration ? ordered_json(g.penetration->depth_diameters) : nullptr;
  return j;
}

ordered_json RunJson(int replicate, const SegregationRun& run,
                     const objectives::SegregationSettings& settings) {
  ordered_json j;
  j["replicate"] = replicate;
  j["seed"] = run.seed;
  j["status"] = run.Status();
  j["message"] = !run.settle.ok() ? run.settle.message : run.analysis_message;
  j["particles"] = run.particles;
  std::vector<int64_t> per_species;
  for (const objectives::Grain& g : run.heap.grains) {
    if (g.species < 0) continue;
    if (g.species >= static_cast<int>(per_species.size())) per_species.resize(g.species + 1, 0);
    ++per_species[g.species];
  }
  j["heap_grains_per_species"] = per_species;
  double mass = 0;
  for (const objectives::Grain& g : run.heap.grains) mass += g.mass_kg;
  j["heap_mass_kg"] = mass;
  if (run.analysis) {
    const objectives::HeapExtent& e = run.analysis->grid.extent();
    j["heap_base_width_m"] = e.x_right_m - e.x_left_m;
    j["heap_height_m"] = e.height_m;
    j["grains_outside_bins"] = run.analysis->counts.outside_count;
  }
  j["mixture_angle_deg"] = run.angle.ok ? ordered_json(run.angle.angle_deg) : nullptr;
  j["angle_message"] = run.angle.message;
  j["funnel_first_out_s"] = run.first_out_s;
  j["funnel_empty_s"] = run.funnel_emptied ? ordered_json(run.empty_s) : nullptr;
  j["discharge_time_s"] = run.funnel_emptied ? ordered_json(run.discharge_time_s) : nullptr;
  j["feed_duration_s"] = run.feed_duration_s;
  j["funnel_feed_limited"] = run.funnel_feed_limited;
  j["funnel_regime"] = run.funnel_regime;
  j["factory_warnings"] = run.settle.factory_warnings;
  j["funnel_mass_flow_kg_s"] = run.funnel_mass_flow_kg_s;
  j["funnel_orifice_diameter_m"] = run.funnel_orifice_diameter_m;
  j["outflow_mass_fraction"] = run.outflow_mass_fraction;
  j["settle_time_s"] = run.settle.settle_time_s;
  j["settled_by"] = run.settle.settled_by.empty() ? nlohmann::ordered_json() : nlohmann::ordered_json(run.settle.settled_by);
  j["surface_change_d"] = run.settle.surface_change_d >= 0 ? nlohmann::ordered_json(run.settle.surface_change_d) : nlohmann::ordered_json();
  j["wall_time_s"] = run.wall_time_s;
  ordered_json tracked = ordered_json::array();
  for (const objectives::TrackedGranule& g : run.tracked) tracked.push_back(TrackedJson(g));
  j["tracked_granules"] = tracked;
  for (const objectives::MechanismObservable& o : objectives::MechanismObservables()) {
    const std::optional<double> v = run.ok() ? o.per_run(run, settings) : std::nullopt;
    j[o.name] = v ? ordered_json(*v) : nullptr;
  }
  return j;
}

}  // namespace

const objectives::Summary* SegregationSpeciesResult::Index(const std::string& name) const {
  for (const NamedEstimate& index : indices)
    if (index.name == name) return &index.value;
  return nullptr;
}

const FloorEstimate* SegregationSpeciesResult::Floor(const std::string& name) const {
  for (const auto& [floor_name, floor] : floors)
    if (floor_name == name) return &floor;
  return nullptr;
}

std::vector<NamedEstimate> SegregationResult::Values() const {
  std::vector<NamedEstimate> values = {
      {"mixture_angle_deg", mixture_angle_deg},
      {"discharge_time_s", discharge_time_s},
      {"penetration_depth_diameters", penetration_depth_diameters}};
  values.insert(values.end(), mechanism.begin(), mechanism.end());
  for (const SegregationSpeciesResult& s : species)
    for (const NamedEstimate& index : s.indices)
      values.push_back({s.species + "." + index.name, index.value});
  return values;
}

SegregationResult SummariseSegregation(const objectives::SegregationSettings& settings,
                                       const std::vector<std::string>& species_names,
                                       std::vector<SegregationRun> runs) {
  SegregationResult out;
  out.settings = settings;
  std::vector<double> angles, discharge, depths;
  for (const SegregationRun& run : runs) {
    if (!run.ok()) continue;
    ++out.replicates_ok;
    if (run.angle.ok) angles.push_back(run.angle.angle_deg);
    discharge.push_back(run.discharge_time_s);
    for (const objectives::TrackedGranule& g : run.tracked)
      if (g.penetration) depths.push_back(g.penetration->depth_diameters);
  }
  for (size_t k = 0; k < species_names.size(); ++k)
    out.species.push_back(
        SpeciesResult(runs, static_cast<int>(k), species_names[k], settings.bins.layers));
  out.mixture_angle_deg = objectives::Summarise(angles);
  out.discharge_time_s = objectives::Summarise(discharge);
  out.tracked_species = species_names.at(settings.TrackedSpecies());
  out.penetration_depth_diameters = objectives::Summarise(depths);
  for (const objectives::MechanismObservable& o : objectives::MechanismObservables()) {
    std::vector<double> per_run;
    for (const SegregationRun& run : runs)
      if (run.ok())
        if (const std::optional<double> v = o.per_run(run, settings)) per_run.push_back(*v);
    out.mechanism.push_back({o.name, objectives::Summarise(per_run)});
  }
  out.runs = std::move(runs);
  return out;
}

ordered_json SegregationResultJson(const SegregationResult& r) {
  const objectives::SegregationSettings& settings = r.settings;
  ordered_json result;
  result["basis"] = {{"2d", "number fraction"}, {"3d", "mass fraction"}};
  result["noise_floor"] = {
      {"method",
       "species labels shuffled among the heap's grains in bins (same positions and "
       "counts); CoV and S_n = CoV/CoV_r(measured) of each shuffled heap"},
      {"shuffles", settings.floor.shuffles},
      {"band", settings.floor.band}};
  result["funnel"] = settings.funnel.enabled;
  result["heap_feed_mass_kg"] = settings.feed.mass_kg;
  result["replicates_ok"] = r.replicates_ok;
  ordered_json species = ordered_json::array();
  for (const SegregationSpeciesResult& s : r.species) species.push_back(SpeciesJson(s));
  result["species"] = species;
  result["mixture_angle_deg"] = StatJson(r.mixture_angle_deg);
  result["discharge_time_s"] = StatJson(r.discharge_time_s);
  result["tracked_species"] = r.tracked_species;
  result["penetration_depth_diameters"] = StatJson(r.penetration_depth_diameters);
  ordered_json mechanism = ordered_json::object();
  for (size_t k = 0; k < r.mechanism.size(); ++k) {
    mechanism[r.mechanism[k].name] = StatJson(r.mechanism[k].value);
    mechanism[r.mechanism[k].name]["meaning"] = objectives::MechanismObservables()[k].meaning;
  }
  result["mechanism"] = mechanism;
  ordered_json runs_json = ordered_json::array();
  for (size_t k = 0; k < r.runs.size(); ++k)
    runs_json.push_back(RunJson(static_cast<int>(k), r.runs[k], settings));
  result["runs"] = runs_json;
  return result;
}

}  // namespace demcal::workflow
