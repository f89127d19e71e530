#pragma once
// The paper's segregation mechanism as observables of the segregation experiment (Alizadeh et
// al. 2018, section 3.5, Figs. 17 and 19): one file per observable in this folder, one line per
// observable in kMechanismObservables (mechanism_observables.cc). Each gives one number per run
// (the mean over the tracked granules, or over the heap's grains of the tracked species); the
// result summarises them over the replicates, so their spread is between heaps, not between
// granules of one heap (which share the heap they land on).
//
// The tracked species is SegregationSettings::TrackedSpecies() (the minor feed component: EP in
// the paper's mixture); the major species is the feed component with the largest mass fraction
// (BP).
#include <optional>
#include <string>
#include <vector>

#include "experiments/segregation/segregation_experiment.h"

namespace demcal::objectives {

struct MechanismObservable {
  const char* name;  // the key in result.json and in the result's Values(), unit in the name
  const char* meaning;
  std::optional<double> (*per_run)(const SegregationRun& run, const SegregationSettings& settings);
};

const std::vector<MechanismObservable>& MechanismObservables();

// The feed component with the largest mass fraction (−1: no feed).
int MajorSpecies(const SegregationSettings& settings);

}  // namespace demcal::objectives
