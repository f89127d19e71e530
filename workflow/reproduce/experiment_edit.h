#pragma once
// Editing a demcal-experiment/1 file as JSON for the stages of `demcal reproduce`: a stage takes
// a bundled or user experiment file, puts the values calibrated so far into it (pair properties
// of interactions.pairs), parses the edited copy with the ordinary reader into the
// ExperimentFile it runs, and writes the copy into its own output folder as the record of what
// was run. Only keys of the file format are written, so the reader validates the copy.
//
//   nlohmann::json e;
//   if (!ReadExperimentJson(path, &e, &error)) ...;
//   SetPairProperty(&e, "EP", "EP", "interfacial_energy_J_m2", 0.046);
//   WriteJsonFile(dir + "/experiment.json", e, &error);
//   ExperimentFile file;
//   if (!ParseEditedExperiment(e, dir + "/experiment.json", &file, &error)) ...;
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "experiments/common/experiment_file.h"

namespace demcal::workflow {

bool ReadExperimentJson(const std::string& path, nlohmann::ordered_json* out, std::string* error);

// The edited document as the experiment file it describes; `source` names it in messages and in
// result.json (the path of its written copy).
bool ParseEditedExperiment(const nlohmann::ordered_json& experiment, const std::string& source,
                           ExperimentFile* out, std::string* error);

// Sets `key` of the (a, b) pair in interactions.pairs (either order), adding the pair (with only
// this key; the file's default fills the rest) if it is not listed.
void SetPairProperty(nlohmann::ordered_json* experiment, const std::string& a, const std::string& b,
                     const std::string& key, double value);

// Gives species `name` the shape of the clump-count loop (workflow/calibration/study_runs.cc):
// `count` spheres on the long axis of the ellipsoid `semi_axes` (proportions only: the species'
// diameter sets the size); count 1 removes any clump (a sphere). No species of that name: no
// change.
void SetSpeciesClump(nlohmann::ordered_json* experiment, const std::string& name,
                     const std::vector<double>& semi_axes, int count);

// Replaces a segregation file's funnel orifice with the fidelity rule D = effective + k d_max
// (experiments/segregation/funnel_geometry.h), keeping the funnel's other dimensions. False
// (nothing changed) when the file pours without a funnel ("funnel": false).
bool SetFunnelOrificeRule(nlohmann::ordered_json* experiment, double effective_orifice_diameter_m,
                          double beverloo_k);

// The pair's `key`, or the interactions.default's, or `fallback`.
double PairProperty(const nlohmann::ordered_json& experiment, const std::string& a,
                    const std::string& b, const std::string& key, double fallback);

}  // namespace demcal::workflow
