#pragma once
// StudyRuns: a loaded study turned into what the calibration driver runs — one run group per
// (experiment file, condition) that a target or candidate target reads, each with its probe
// (parsed and validated at the run fidelity), its full-scale model, the parameter space
// resolved to that model's materials and the fidelity applied after the parameters; the target
// bindings; the journal fingerprint.
//
//   StudyRuns runs;
//   if (!BuildStudyRuns(study, quick, clump_count, &runs, &error)) ...;
//   calibrate::TargetEvaluator evaluator(study.space, runs.groups, runs.bindings, ...);
#include <memory>
#include <string>
#include <vector>

#include "calibrate/target_evaluator.h"
#include "objectives/common/fidelity.h"
#include "workflow/calibration/study_file.h"

namespace demcal::workflow {

struct StudyRuns {
  std::vector<std::unique_ptr<calibrate::ExperimentProbe>> probes;  // per experiment
  std::vector<objectives::Fidelity> fidelities;                     // per experiment
  std::vector<calibrate::RunGroup> groups;
  std::vector<calibrate::TargetBinding> bindings;  // the targets, then the candidate targets
  std::string fingerprint;                         // what the journal's records depend on
};

// clump_count > 0: every experiment's species study.clump_count.species becomes that many
// spheres (clump_count = 1: a plain sphere).
bool BuildStudyRuns(const StudyFile& study, bool quick, int clump_count, StudyRuns* out,
                    std::string* error);

}  // namespace demcal::workflow
