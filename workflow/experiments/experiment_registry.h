#pragma once
// The experiments demcal knows, by the name experiment files give in "experiment": for each,
// the runner of `demcal experiment` (experiment_runner.h) and, where the experiment can be a
// calibration target, the maker of its probe (calibrate/experiment_probe.h: one replicate in,
// named observables out). Adding an experiment is its runner and probe files plus one line in
// experiment_registry.cc.
//
//   const ExperimentKind* kind = FindExperimentKind(file.experiment);
//   std::unique_ptr<calibrate::ExperimentProbe> probe = kind->make_probe(file, model, &error);
#include <memory>
#include <string>
#include <vector>

#include "calibrate/experiment_probe.h"
#include "core/scene/scene.h"
#include "workflow/experiments/experiment_runner.h"
#include "workflow/files/experiment_file.h"

namespace demcal::workflow {

// The probe of `file` for a model at its run fidelity: the section parsed against that model
// and one run's scene validated; nullptr with *error otherwise.
using ProbeMaker = std::unique_ptr<calibrate::ExperimentProbe> (*)(const ExperimentFile& file,
                                                                   const core::Scene& model,
                                                                   std::string* error);

struct ExperimentKind {
  const char* name;
  ExperimentRunner run;
  ProbeMaker make_probe;  // nullptr: not a calibration target yet
};

const ExperimentKind* FindExperimentKind(const std::string& name);
std::vector<std::string> ExperimentKindNames();

}  // namespace demcal::workflow
