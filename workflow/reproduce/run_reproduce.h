#pragma once
// `demcal reproduce NAME|WORKFLOW.json --out DIR [--quick] [--threads N] [--quiet]
// [--bracket-points K] [--calibrations-in-sequence]`: runs the
// stages of a demcal-workflow/1 file (stages.h) in order, each journalled in DIR/stages.jsonl
// (stage_journal.h): run again with the same --out after a kill and finished stages and finished
// replicate runs are not repeated. Then writes DIR/summary.json (paper vs demcal, summary_table.h),
// DIR/report.html and DIR/report.md (reproduce_report.h), DIR/params/<scenario>.json and
// .liggghts. Progress and per-stage times on stderr. docs/reproduce.md lists every output.
// Exit codes: 0 done, 2 bad input (nothing ran), 4 an output could not be written, 1 internal.
#include <ostream>
#include <string>

namespace demcal::workflow {

struct ReproduceOptions {
  std::string workflow;  // a bundled name ("alizadeh2018") or a workflow file path
  std::string out_dir;
  bool quick = false;
  int threads = 0;
  bool quiet = false;
  int bracket_points = 1;                 // candidates per round of the calibrations' bracket
  bool calibrations_in_sequence = false;  // stage 1's and 3's calibrations one at a time
  std::string repo_root;  // where bundled workflows are looked up (default: the source tree)
};

int RunReproduce(const ReproduceOptions& options, std::ostream& log);

}  // namespace demcal::workflow
