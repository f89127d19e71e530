#pragma once
// The runners of `demcal experiment`: one per experiment, in its room
// (experiments/<name>/<name>_runner.cc), found through the registry (experiment_registry.h).
// A runner turns a parsed file into runs, writes DIR/result.json plus its tables and pictures
// from its typed result, and returns that result (experiment_result.h).
#include <nlohmann/json.hpp>
#include <ostream>
#include <string>

#include "experiments/common/experiment_file.h"
#include "experiments/common/experiment_result.h"
#include "objectives/common/fidelity.h"

namespace demcal::workflow {

struct ExperimentContext {
  std::string out_dir;
  int replicates = 1;             // from the file or --replicates
  objectives::Fidelity fidelity;  // the file's, or its quick one with --quick
  int threads = 0;                // workers for side-by-side replicates (0: all cores)
  bool quiet = false;
};

using ExperimentRunner = ExperimentResult (*)(const ExperimentFile&, const ExperimentContext&,
                                              std::ostream&);

// The fields every result.json starts with: format, experiment, version, source, description,
// fidelity, seed, replicates.
nlohmann::ordered_json ResultHeader(const ExperimentFile& file, const ExperimentContext& context);
nlohmann::ordered_json FidelityJson(const objectives::Fidelity& fidelity);

}  // namespace demcal::workflow
