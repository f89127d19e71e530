#pragma once
// SharedRunGroups: run groups whose simulations are the same run, merged into one.
//
// A study lists one run group per (experiment, condition). Where the condition does not enter
// the model of a setting (a coating level that no parameter or effect reads: every effect but
// adhesion, and the base model of the diagnosis studies), the groups of one experiment build
// the same scene, and since replicate r has the same seed in every group (common random
// numbers, study_model.h) they run the same simulation and give bit-identical values. Running
// each once and binding every target of the merged groups to the one that stays gives the same
// predictions, replicate spreads and pooled scatter at a fraction of the runs (the rig heaps at
// 0, 1.5 and 3 wt%: one run where there were three). Nothing statistical changes: the values
// were already one draw shared by those rows.
//
// Two groups are merged when they have the same probe (experiment) and their prepared scenes
// (the study's parameters applied with each group's condition, then the setting's effects and
// the fidelity) have the same core::SceneFingerprint and time settings at two parameter points
// (unit coordinates 0.3 and 0.7 in every direction, so a parameter that scales with the
// condition, a + b·c, cannot look condition-free by vanishing at one point).
#include <string>
#include <vector>

#include "calibrate/target_evaluator.h"

namespace demcal::diagnose {

struct MergedRunGroups {
  std::vector<calibrate::RunGroup> groups;         // the groups that run, in their first order
  std::vector<calibrate::TargetBinding> bindings;  // the targets, bound to those groups
  int merged = 0;                                  // groups dropped as duplicates
};

// `space`: the study's parameter space (its FromUnit gives the SI values each group applies).
MergedRunGroups MergeSharedRunGroups(const std::vector<calibrate::RunGroup>& groups,
                                     const std::vector<calibrate::TargetBinding>& bindings,
                                     const calibrate::ParameterSpace& space);

// Per target the simulated quantity it reads (Prediction::source): the index of the first target
// bound to the same run group and observable. Targets of merged groups read one simulated mean
// and get one source; every other target its own.
std::vector<int> BindingSources(const std::vector<calibrate::TargetBinding>& bindings);

}  // namespace demcal::diagnose
