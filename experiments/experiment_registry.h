#pragma once
// The experiments demcal knows, by the name experiment files give in "experiment". Each is a room
// of its own (experiments/<name>/: physics, section reader, runner, probe) that defines one
// ExperimentKind in <name>_kind.cc; experiment_registry.cc lists them. Every list of experiments
// (the file reader's allowed names, the command line's choices and help, the study reader's
// calibration targets, the fuzzer) asks this registry.
//
//   const ExperimentKind* kind = FindExperimentKind(file.experiment);
//   std::unique_ptr<calibrate::ExperimentProbe> probe = kind->make_probe(file, model, &error);
#include <memory>
#include <string>
#include <vector>

#include "calibrate/experiment_probe.h"
#include "core/scene/scene.h"
#include "experiments/common/experiment_file.h"
#include "experiments/common/experiment_runner.h"

namespace demcal::workflow {

// The probe of `file` for a model at its run fidelity: the section parsed against that model
// and one run's scene validated; nullptr with *error otherwise.
using ProbeMaker = std::unique_ptr<calibrate::ExperimentProbe> (*)(const ExperimentFile& file,
                                                                   const core::Scene& model,
                                                                   std::string* error);
// Parses the file's section against its own model; false with *error naming the field.
using SectionChecker = bool (*)(const ExperimentFile& file, std::string* error);

struct ExperimentKind {
  const char* name;         // the "experiment" value, and the key of its section
  const char* description;  // a few words for --help ("angle of repose")
  ExperimentRunner run;
  ProbeMaker make_probe;  // nullptr: not a calibration target
  SectionChecker check_section;
};

const ExperimentKind* FindExperimentKind(const std::string& name);
std::vector<std::string> ExperimentKindNames();
// The experiments a calibration study can fit against (those with a probe).
std::vector<std::string> CalibratableExperimentNames();
// "aor, discharge, segregation": for messages and help.
std::string JoinNames(const std::vector<std::string>& names);

}  // namespace demcal::workflow
