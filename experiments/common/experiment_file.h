#pragma once
// ExperimentFile: a parsed "demcal-experiment/1" parameter file — the particle model (materials,
// species, interactions, contact model: the same sections as a scene file), the fidelity, the
// seed and replicate count, and the experiment's own section ("aor", "discharge" or
// "segregation"), which that experiment's runner parses. Documented in docs/experiments.md.
//
//   ExperimentFile file;  std::string error;
//   if (!LoadExperimentFile(path, &file, &error)) { std::cerr << error; }
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>

#include "files/json_fields.h"
#include "files/scene_file.h"
#include "core/scene/scene.h"
#include "objectives/common/fidelity.h"

namespace demcal::workflow {

inline constexpr const char* kExperimentFormat = "demcal-experiment/1";

struct ExperimentFile {
  std::string source;
  std::string description;
  std::string experiment;  // "aor", "discharge", "segregation"
  uint64_t seed = 1;
  int replicates = 1;
  core::Scene model;                  // materials, species, interactions, contact model
  objectives::Fidelity fidelity = objectives::DefaultCalibrationFidelity();
  objectives::Fidelity quick_fidelity = objectives::QuickFidelity();
  nlohmann::json section;             // the experiment's own section
  OutputSettings output;
  // The whole document as read: a calibration journal's records depend on it (study_runs.cc),
  // so a parsed file carries it rather than its path being read again.
  nlohmann::json document;
};

bool ParseExperimentJson(const nlohmann::json& document, const std::string& source,
                         ExperimentFile* out, std::string* error);
bool LoadExperimentFile(const std::string& path, ExperimentFile* out, std::string* error);

// Reads a fidelity object ({"name", "size_scale", "stiffness_scale", "rayleigh_fraction"}).
void ParseFidelity(const nlohmann::json& value, const std::string& path,
                   objectives::Fidelity* fidelity, JsonStatus* status);

}  // namespace demcal::workflow
