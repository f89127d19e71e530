#pragma once
// The stages of `demcal reproduce` (Alizadeh et al. 2018, Fig. 4), one file each, in order:
//   species            stage_species.cc           per species: the friction (and clump count)
//                                                 matching its measured repose angle
//   cohesion           stage_cohesion.cc          Coh of the coated species, Γ carried to the
//                                                 simulation stiffness at constant Coh
//   gamma_per_coating  stage_gamma_per_coating.cc Γ of the coated pair per coating level,
//                                                 bracketed on that level's angle
//   gamma_curve        stage_gamma_curve.cc       Γ(w) fitted with Ceres, covariance and band
//   dissimilar_pairs   stage_dissimilar_pairs.cc  Γ/2 carried to each coated–uncoated pair
//   segregation        stage_segregation.cc       the ternary heap: uncoated, coated, excessive
//   fidelity_check     stage_fidelity_check.cc    the coated heap at a finer fidelity
// Each returns its result (journalled by the driver, run_reproduce.cc) with a "values" object
// for summary.json; false with *error for bad input or an output that cannot be written (a
// calibration that does not match is a result, not an error).
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "workflow/reproduce/calibration_step.h"
#include "workflow/reproduce/reproduce_context.h"

namespace demcal::workflow {

using StageFunction = bool (*)(ReproduceContext& ctx, nlohmann::json* result, std::string* error);

struct Stage {
  const char* name;
  const char* title;  // for progress lines and the report
  StageFunction run;
};

bool RunSpeciesStage(ReproduceContext& ctx, nlohmann::json* result, std::string* error);
bool RunCohesionStage(ReproduceContext& ctx, nlohmann::json* result, std::string* error);
bool RunGammaPerCoatingStage(ReproduceContext& ctx, nlohmann::json* result, std::string* error);
bool RunGammaCurveStage(ReproduceContext& ctx, nlohmann::json* result, std::string* error);
bool RunDissimilarPairsStage(ReproduceContext& ctx, nlohmann::json* result, std::string* error);
bool RunSegregationStage(ReproduceContext& ctx, nlohmann::json* result, std::string* error);
bool RunFidelityCheckStage(ReproduceContext& ctx, nlohmann::json* result, std::string* error);

// The calibrations of stage 1 (species k) and stage 3 (one coating level, whose angle row is in
// `table`, on `experiment`), in folders under `dir`: the stages run them, and the whole-workflow
// check (workflow_checks.h) parses them before stage 1.
CalibrationStep SpeciesStep(const WorkflowFile& w, size_t k, const std::string& dir);
CalibrationStep CoatingLevelStep(const WorkflowFile& w, double level, const std::string& table,
                                 const std::string& experiment, double start,
                                 const std::string& dir);
// The table holding the level's angle_deg row of the coated material: the measurements, else
// the synthetic table; empty when neither has it, with the reason in *why.
void CoatingLevelTable(const WorkflowFile& w, double level, std::string* table, std::string* why);

// The stages in order.
const std::vector<Stage>& ReproduceStages();

// {"mean": m, "sem": s, "note": n, "synthetic": b} for a stage's "values" (NaN -> null).
nlohmann::json ValueJson(double mean, double sem, const std::string& note = "",
                         bool synthetic = false);

}  // namespace demcal::workflow
