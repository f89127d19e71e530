#pragma once
// WorkflowFile: a parsed `demcal-workflow/1` file, the paper's method (Alizadeh et al. 2018,
// Fig. 4) as data a user can point at their own campaign: which experiment files model each
// species, which measurement table holds the angles, the coating levels, the curve form, the
// segregation scenarios, the fidelity check and the reference numbers to compare with.
// docs/reproduce.md documents every key; the bundled one is datasets/alizadeh2018/workflow.json.
// Paths are relative to the workflow file's folder. Errors name the file and the key's path and
// the allowed values: "workflow.json: coating.levels_wt_pct[2]: must be in (0, 100]".
//
//   WorkflowFile w;  std::string error;
//   if (!LoadWorkflowFile(path, &w, &error)) { std::cerr << error; return kExitInvalidInput; }
#include <limits>
#include <string>
#include <vector>

#include "calibrate/cohesion_scaling.h"
#include "calibrate/parameter_curve.h"

namespace demcal::workflow {

inline constexpr const char* kWorkflowFormat = "demcal-workflow/1";

// The aspect ratio a of the clump shape [a, 1, 1] calibrated per clump count (the paper gives
// none): bounds, first candidate and the most heaps' candidates one count may cost.
struct AspectRatioSearch {
  double min = 1, max = 3.5, start = 2;  // a/c of the prolate spheroid, dimensionless
  int max_evaluations = 6;               // candidates per count (each `replicates` heaps)
  bool enabled = false;
};

// Stage 1: one species' repose angle, matched by one pair property of the species with itself.
struct WorkflowSpecies {
  std::string name;             // the material (and species) in the experiment file
  std::string experiment_file;  // an `aor` demcal-experiment/1 file (resolved path)
  std::string property = "rolling_friction";  // sliding_friction or rolling_friction
  double min = 0, max = 1, start = 0;
  std::vector<int> clump_counts;  // empty: the experiment file's shape; else the n loop
  std::vector<double> semi_axes;  // for the clump loop: a >= b >= c > 0 (any unit)
  // The paper's shape calibration (section 2.4): the property held at `start` (Table 1's value)
  // and each clump count judged by its angle there; false: the property calibrated per count.
  bool hold = false;
  // With clump_counts and hold: per count n >= 2 the aspect ratio is calibrated instead of
  // taken from semi_axes, and the counts stop at the first that matches
  // (workflow/reproduce/shape_search.h).
  AspectRatioSearch aspect_ratio;
};

// Stages 3–5: the coated species, its levels and the curve.
struct WorkflowCoating {
  std::string material;         // "EP"
  std::string experiment_file;  // `aor` file of the coated species (resolved path)
  std::string covariate = "coating_PEG_wt_pct";
  std::vector<double> levels;   // coating levels calibrated, each > 0
  double gamma_min_J_m2 = 0, gamma_max_J_m2 = 0.6;
  calibrate::CurveForm curve_form = calibrate::CurveForm::kLinear;
  std::vector<std::string> partners;  // dissimilar pairs: the uncoated species (stage 5)
  std::vector<double> partner_radii_m;  // their equivalent-volume radii, same order
  double coated_radius_m = 0;           // R* of the coated pair (the granule radius)
};

// A pair property of the heap that no stage calibrates, set in every scenario: e.g. the EP–BP
// rolling friction, which Table 1 gives only per material (the file takes the pair's mean) and
// no measured angle holds (docs/reproduce_clumps.md brackets it). `note` says why the value.
struct PairOverride {
  std::string material_a, material_b;
  std::string property;  // rolling_friction or sliding_friction
  double value = 0;
  std::string note;
};

// Stage 6: the ternary heap under three scenarios.
struct WorkflowSegregation {
  std::string experiment_file;  // a `segregation` file (resolved path)
  int replicates = 2;           // per scenario at the default fidelity
  int quick_replicates = 1;     // with --quick
  double coated_wt_pct = 2.5;   // the "coated" scenario's level (Γ from the curve)
  double excessive_gamma_J_m2 = 0.25;  // every EP contact in the "excessive" scenario
  // > 0: the default fidelity's coarse-graining and stiffness factor, replacing the experiment
  // file's (its quick fidelity stays); 0: the file's own.
  double size_scale = 0, stiffness_scale = 0;
  // > 0: the funnel's orifice rule (funnel_geometry.h) replacing the experiment file's, for
  // grains that meter differently from those the file's rule was fitted on ("funnel_orifice":
  // effective_orifice_diameter_m, beverloo_k, note).
  double funnel_effective_orifice_diameter_m = 0;
  double funnel_beverloo_k = 0;
  std::string funnel_note;  // where the rule comes from
  std::vector<PairOverride> pair_overrides;  // applied after stage 1's values, in every scenario
  bool enabled = true;
};

// Stage 7: the coated species re-run at a finer fidelity with the calibrated Γ.
struct WorkflowFidelityCheck {
  double wt_pct = 0.5;
  double size_scale = 2, stiffness_scale = 0.1;
  int replicates = 2;
  bool enabled = true;
};

// A number of the paper to put beside demcal's in summary.json.
struct ReferenceValue {
  std::string key;       // one of ReferenceKeys()
  std::string quantity;  // words for the report
  double value = std::numeric_limits<double>::quiet_NaN();  // NaN: a figure, no number
  double uncertainty = 0;            // of the reference value (0: none given)
  std::string comparison = "equal";  // "equal", "at_least", "at_most"
  std::string unit;
  std::string source;
};

struct WorkflowFile {
  std::string source;       // the file's path
  std::string fingerprint;  // of its content (the stage journal's header)
  std::string name, description, shape_assumption;
  std::string measurements;            // the measurement table (resolved path)
  std::string synthetic_measurements;  // optional second table for synthetic rows (resolved)
  double angle_uncertainty_deg = 1;
  std::string angle_uncertainty_note;
  int replicates = 2;                  // AoR replicates per candidate
  std::vector<WorkflowSpecies> species;
  calibrate::CohesionInputs cohesion;
  WorkflowCoating coating;
  WorkflowSegregation segregation;
  WorkflowFidelityCheck fidelity_check;
  std::vector<ReferenceValue> reference;
};

// The keys summary.json knows how to fill (reference[].key must be one).
const std::vector<std::string>& ReferenceKeys();

bool LoadWorkflowFile(const std::string& path, WorkflowFile* out, std::string* error);

// "alizadeh2018" -> <repo>/datasets/alizadeh2018/workflow.json if it exists; any other argument
// is returned as given (a path). `repo_root` is where the bundled datasets live.
std::string ResolveWorkflowName(const std::string& name_or_path, const std::string& repo_root);

}  // namespace demcal::workflow
