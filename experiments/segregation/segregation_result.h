#pragma once
// The result of `demcal experiment segregation` (SegregationResult) and its result.json: per
// species the segregation indices as mean and standard error over the replicates that
// succeeded, with the random-mixture floor beside them, the mixture angle, the funnel discharge
// time, the tracked granules, and every run. Bases follow the paper: the 2D (face) indices use
// number fractions (image analysis counts granules), the 3D ones mass fractions (section 3.2);
// DIR/segregation_indices_r<k>.csv holds both bases for every region.
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "experiments/common/experiment_result.h"
#include "experiments/segregation/segregation_experiment.h"

namespace demcal::workflow {

// The random-mixture floor of one index (of CoV or of S_n): its mean and band edges, each
// averaged over the ok runs that have one (n of them; n = 0: none).
struct FloorEstimate {
  double mean = 0, low = 0, high = 0;
  size_t n = 0;
};

struct LayerEstimate {
  objectives::Summary cov;  // mass-basis CoV of the layer
  FloorEstimate floor;
};

struct SegregationSpeciesResult {
  std::string species;
  // cov_2d_front, cov_r_2d_front, s_n_2d_front, cov_2d_back, cov_r_2d_back, s_n_2d_back,
  // cov_3d, cov_r_3d, s_n_3d, mean_mass_fraction_3d, outflow_mass_fraction (of all that left
  // the funnel: Fig. 16's average level), in this order.
  std::vector<NamedEstimate> indices;
  // cov_2d_front_floor, s_n_2d_front_floor, cov_2d_back_floor, s_n_2d_back_floor,
  // cov_3d_floor, s_n_3d_floor, in this order.
  std::vector<std::pair<std::string, FloorEstimate>> floors;
  std::vector<LayerEstimate> cov_per_layer_3d;  // layer 1 first

  const objectives::Summary* Index(const std::string& name) const;  // nullptr: no such index
  const FloorEstimate* Floor(const std::string& name) const;        // nullptr: no such floor
};

struct SegregationResult {
  ExperimentStatus status = ExperimentStatus::kInvalidInput;
  objectives::SegregationSettings settings;
  int replicates_ok = 0;
  std::vector<SegregationSpeciesResult> species;  // in the model's species order
  objectives::Summary mixture_angle_deg, discharge_time_s, penetration_depth_diameters;
  std::string tracked_species;
  // The mechanism observables (mechanism/mechanism_observables.h), in their registry's order.
  std::vector<NamedEstimate> mechanism;
  std::vector<objectives::SegregationRun> runs;  // in replicate order
  // mixture_angle_deg, discharge_time_s, penetration_depth_diameters, the mechanism
  // observables, then "<species>.<index>" for every species and index.
  std::vector<NamedEstimate> Values() const;
};

// The summaries of `runs` (in replicate order); status left for the runner to set.
SegregationResult SummariseSegregation(const objectives::SegregationSettings& settings,
                                       const std::vector<std::string>& species_names,
                                       std::vector<objectives::SegregationRun> runs);

// Everything of result.json after ResultHeader.
nlohmann::ordered_json SegregationResultJson(const SegregationResult& result);

}  // namespace demcal::workflow
