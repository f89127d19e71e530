#pragma once
// The section readers of a study file (study_file.cc, study_targets.cc, study_parameters.cc),
// shared by the format 1 and format 2 readers. Each records the first error in *status with its
// JSON path.
#include <nlohmann/json.hpp>
#include <string>

#include "files/json_fields.h"
#include "workflow/calibration/study_file.h"

namespace demcal::workflow {

// The experiment file at `path` (relative to the study), loaded once: its index in
// study->experiments.
int StudyExperimentIndex(const std::string& path, const std::string& json_path, StudyFile* study,
                         JsonStatus* status);

void ParseStudyTarget(const nlohmann::json& j, const std::string& path, const std::string& table,
                      StudyFile* study, JsonStatus* status);
void ParseStudyCandidateTarget(const nlohmann::json& j, const std::string& path, StudyFile* study,
                               JsonStatus* status);
// The format 1 "measurement": one angle_deg target of study->experiments[0].
void ParseLegacyMeasurement(const nlohmann::json& j, const std::string& path, StudyFile* study,
                            JsonStatus* status);

void ParseStudyParameter(const nlohmann::json& j, const std::string& path, StudyFile* study,
                         JsonStatus* status);
void ParseStudyConstraint(const nlohmann::json& j, const std::string& path, StudyFile* study,
                          JsonStatus* status);
// After parsing: refuses a study that could never evaluate a candidate or holds a parameter that
// never acts (study_checks.cc); the message names the field.
bool CheckStudyEvaluable(const StudyFile& study, std::string* error);

void ParseClumpCount(const nlohmann::json& j, const std::string& path, StudyFile* study,
                     JsonStatus* status);

}  // namespace demcal::workflow
