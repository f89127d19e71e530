#pragma once
// StudyFile: a parsed calibration study (docs/calibration.md documents every key).
//  - "demcal-study/2": a list of targets, each an observable of an experiment file under a
//    condition, matched to a row of a tidy measurement table (measurement_table.h); parameters
//    that are global, per condition ("when") or curves over a covariate; constraints; optional
//    candidate targets (measurements the study could add: "which measurement would help"); an
//    optional integer outer loop over the clump sphere count of a species.
//  - "demcal-study/1" (one experiment file, one measurement): read as a study with one target.
// Paths are relative to the study file's folder.
//
// The parsed study holds every experiment file and measurement it names, read once: it is a
// self-contained value (CalibrateStudy, run_study.h, reads no path of it again).
//
//   StudyFile study;  std::string error;
//   if (!LoadStudyFile(path, &study, &error)) { std::cerr << error; }
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "calibrate/calibration.h"
#include "calibrate/condition.h"
#include "calibrate/parameter_space.h"
#include "calibrate/target.h"
#include "core/math/vec3.h"
#include "experiments/common/experiment_file.h"

namespace demcal::workflow {

struct StudyExperiment {
  std::string path;  // resolved against the study's folder
  ExperimentFile file;
};

struct StudyTarget {
  calibrate::Target target;      // name, observable, measured value, uncertainty, source
  int experiment = 0;            // index into StudyFile::experiments
  calibrate::Condition condition;  // what differs for this target (from its measurement row)
  std::string provenance;        // measured, inferred, synthetic (from the table)
  int repeats = 0;               // how many repeats the value is the mean of (0: not stated)
  std::string note;              // e.g. why an assumed uncertainty was chosen
};

// A measurement the study could add: its experiment, observable, condition and the uncertainty
// it would be measured with (no value: it is not measured yet).
struct StudyCandidateTarget {
  std::string name, observable;
  int experiment = 0;
  calibrate::Condition condition;
  double uncertainty = 0;
};

// The integer outer loop of the paper's section 2.4: the clump sphere count of one species,
// each count an equal-volume n-sphere chain of the spheroid/ellipsoid with these semi-axes.
struct ClumpCountSearch {
  std::string species;
  core::Vec3 semi_axes;   // any one length unit; a >= b >= c > 0
  std::vector<int> counts;  // ascending, in [1, 5]
  bool enabled() const { return !counts.empty(); }
};

struct StudyFile {
  std::string source;
  std::string format;
  std::string description;
  std::vector<StudyExperiment> experiments;
  std::vector<StudyTarget> targets;
  std::vector<StudyCandidateTarget> candidate_targets;
  // Material indices of experiments[0]'s model; ResolveSpaceFor re-resolves them by name.
  calibrate::ParameterSpace space;
  std::vector<std::pair<std::string, std::string>> parameter_materials;  // per parameter
  std::vector<std::pair<std::string, std::string>> curve_materials;      // per curve
  // The JSON path each came from, for messages: "parameters[2]" or
  // "parameters[0].curve.coefficients[1]" per parameter, "parameters[0].curve" per curve,
  // "constraints[0].non_decreasing" per space.non_decreasing chain.
  std::vector<std::string> parameter_paths, curve_paths, constraint_paths;
  ClumpCountSearch clump_count;
  calibrate::CalibrationOptions options;
  int replicates = 0;  // 0: the first experiment file's
  uint64_t seed = 0;   // 0: the first experiment file's
  bool has_seed = false;
  const ExperimentFile& experiment() const { return experiments.front().file; }
};

bool LoadStudyFile(const std::string& path, StudyFile* out, std::string* error);
// A study document already in memory; `path` is where it lives or would live: its relative
// paths resolve against that folder, and messages and result.json name it.
bool ParseStudyJson(const nlohmann::json& document, const std::string& path, StudyFile* out,
                    std::string* error);

// The study's parameter space with material indices of `model` (materials found by name).
bool ResolveSpaceFor(const StudyFile& study, const core::Scene& model,
                     calibrate::ParameterSpace* out, std::string* error);

// Paths in a study are relative to its folder.
std::string ResolveStudyPath(const std::string& study, const std::string& path);
// A JSON condition object ({"coating_PEG_wt_pct": 0.5, "test": "slot"}) as a Condition.
void ParseCondition(const nlohmann::json& value, const std::string& path,
                    calibrate::Condition* out, JsonStatus* status);

}  // namespace demcal::workflow
