#pragma once
// ReproduceContext: what every stage of `demcal reproduce` shares — the workflow file, the output
// directory, the fidelity switch, the stage journal and the log (progress on stderr). A stage is
// a function (stages.h) that reads the results of the stages before it from `results` and
// returns its own result as JSON, which the driver journals and hands to the next stages; a
// stage's result carries a "values" object (summary key -> {mean, sem, note, synthetic}) that
// feeds summary.json.
//
// Thread-safety: one driver thread; stages may run replicates side by side internally.
#include <nlohmann/json.hpp>
#include <ostream>
#include <string>

#include "workflow/reproduce/stage_journal.h"
#include "workflow/reproduce/workflow_file.h"

namespace demcal::workflow {

struct ReproduceContext {
  const WorkflowFile* workflow = nullptr;
  std::string out_dir;
  bool quick = false;
  int threads = 0;  // runs side by side (0: all cores)
  bool quiet = false;
  // Candidates per refining round of every calibration's bracket (k-section; 1: regula falsi,
  // one candidate a round). Part of the results, so part of the stage journal's fingerprint.
  int bracket_points = 1;
  // Stage 1's and stage 3's calibrations one after another instead of together
  // (calibration_steps.h); the results are the same either way.
  bool calibrations_in_sequence = false;
  std::ostream* log = nullptr;
  StageJournal* journal = nullptr;
  nlohmann::json results = nlohmann::json::object();  // stage name -> its result
  // DIR/<stage> (created by the driver before the stage runs).
  std::string StageDir(const std::string& stage) const { return out_dir + "/" + stage; }
};

}  // namespace demcal::workflow
