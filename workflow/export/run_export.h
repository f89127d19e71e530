#pragma once
// `demcal export liggghts EXPERIMENT.json --out DIR`: reads the experiment file (and a
// calibration's calibrated_params.json), builds the scene at the chosen fidelity and writes the
// deck and its files into DIR (liggghts_deck.h lists them). A part LIGGGHTS-PUBLIC cannot
// express is refused with a message naming it; nothing is written then.
//
//   ExportOptions o;  o.experiment_path = "examples/aor_bp.json";  o.out_dir = "deck";
//   int code = RunExportLiggghts(o, std::cerr);  // exit code (outputs/exit_codes.h)
#include <ostream>

#include "workflow/export/liggghts_deck.h"

namespace demcal::workflow {

int RunExportLiggghts(const ExportOptions& options, std::ostream& log);

}  // namespace demcal::workflow
