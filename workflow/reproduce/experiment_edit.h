#pragma once
// Editing a demcal-experiment/1 file as JSON for the stages of `demcal reproduce`: a stage takes
// a bundled or user experiment file, puts the values calibrated so far into it (pair properties
// of interactions.pairs), and writes the edited copy into its own output folder, where it is
// both the input of the run and the record of what was run. Only keys of the file format are
// written, so the copy is validated by the ordinary reader when it is run.
//
//   nlohmann::json e;
//   if (!ReadExperimentJson(path, &e, &error)) ...;
//   SetPairProperty(&e, "EP", "EP", "interfacial_energy_J_m2", 0.046);
//   WriteJsonFile(dir + "/experiment.json", e, &error);
#include <nlohmann/json.hpp>
#include <string>

namespace demcal::workflow {

bool ReadExperimentJson(const std::string& path, nlohmann::ordered_json* out, std::string* error);

// Sets `key` of the (a, b) pair in interactions.pairs (either order), adding the pair (with only
// this key; the file's default fills the rest) if it is not listed.
void SetPairProperty(nlohmann::ordered_json* experiment, const std::string& a, const std::string& b,
                     const std::string& key, double value);

// The pair's `key`, or the interactions.default's, or `fallback`.
double PairProperty(const nlohmann::ordered_json& experiment, const std::string& a,
                    const std::string& b, const std::string& key, double fallback);

}  // namespace demcal::workflow
