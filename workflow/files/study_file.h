#pragma once
// StudyFile: a parsed "demcal-study/1" calibration study — which experiment file to run
// (demcal-experiment/1, path relative to the study), which pair properties to vary within which
// bounds, the measurement to match (from a dataset in datasets/, with its provenance), the
// optimiser and its budget, replicates and seed. Documented in docs/calibration.md.
//
//   StudyFile study;  std::string error;
//   if (!LoadStudyFile(path, &study, &error)) { std::cerr << error; }
#include <cstdint>
#include <string>

#include "workflow/files/experiment_file.h"
#include "calibrate/calibration.h"
#include "calibrate/parameter_space.h"

namespace demcal::workflow {

inline constexpr const char* kStudyFormat = "demcal-study/1";

struct StudyFile {
  std::string source;
  std::string description;
  std::string experiment_path;  // resolved against the study's folder
  ExperimentFile experiment;
  calibrate::ParameterSpace space;
  calibrate::Measurement measurement;
  std::string measurement_note;  // e.g. why an assumed uncertainty was chosen
  calibrate::CalibrationOptions options;
  int replicates = 0;  // 0: the experiment file's
  uint64_t seed = 0;   // 0: the experiment file's
  bool has_seed = false;
};

bool LoadStudyFile(const std::string& path, StudyFile* out, std::string* error);

}  // namespace demcal::workflow
