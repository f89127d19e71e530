#pragma once
// The report of `demcal reproduce`: DIR/report.html (self-contained: inline SVG, no scripts, no
// network; outputs/html_report.h) and the same document as DIR/report.md with its
// figures in DIR/figures/. The verdict comes first: headline lines computed from the summary rows
// (report_headline.h) and the key figures in the paper's styles (Γ(w), the angle against the
// coating, the segregation indices); then paper vs demcal (the summary table with short verdicts,
// its notes numbered below it, each once), one section per stage (its numbers, its other plots,
// its output folder), where the time went, and the output files. Everything resting on synthetic
// data carries a "synthetic" badge.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "workflow/reproduce/summary_table.h"
#include "workflow/reproduce/workflow_file.h"

namespace demcal::workflow {

struct ReportInputs {
  const WorkflowFile* workflow = nullptr;
  const nlohmann::json* results = nullptr;  // stage name -> result
  const std::vector<SummaryRow>* rows = nullptr;
  const nlohmann::json* timings = nullptr;  // stage name -> wall time [s]
  bool quick = false;
  std::string out_dir;
};

bool WriteReproduceReport(const ReportInputs& in, std::string* error);

}  // namespace demcal::workflow
