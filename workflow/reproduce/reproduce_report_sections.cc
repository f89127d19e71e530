// The later sections of the reproduce report (reproduce_report.h): segregation with its indices
// and heap face pictures, the fidelity check, where the time went, and the output files.
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "core/io/input_file.h"
#include "files/input_file.h"
#include "outputs/html_report.h"
#include "workflow/reproduce/reproduce_report.h"

namespace demcal::workflow {
namespace {

namespace fs = std::filesystem;

// j[key], or null when j is not an object or lacks the key (a skipped or failed stage).
const nlohmann::json& At(const nlohmann::json& j, const char* key) {
  static const nlohmann::json kNull;
  return j.is_object() && j.contains(key) ? j[key] : kNull;
}


std::string Fmt(const nlohmann::json& j, const char* format = "%.3g") {
  if (!j.is_number()) return "–";
  char text[48];
  std::snprintf(text, sizeof(text), format, j.get<double>());
  return text;
}

std::string Stat(const nlohmann::json& scenario, const std::string& key) {
  if (!scenario.contains(key)) return "–";
  const nlohmann::json& s = scenario[key];
  return Fmt(At(s, "mean")) + (At(s, "sem").is_number() ? " ± " + Fmt(At(s, "sem")) : "");
}

// The file's text, or "" when it cannot be read (missing, or not a regular file: a FIFO would
// block the report for ever).
std::string ReadText(const std::string& path) {
  std::string text;
  if (!core::io::ReadRegularFile(path, "figure", kMaxTableInputBytes, {}, &text, nullptr))
    return "";
  return text;
}

// One figure per scenario from replicate 0's file `name` (skipped where the run wrote none);
// `caption` holds one %s for the scenario's name.
bool ScenarioFigures(const nlohmann::json& seg, const std::string& name, const std::string& caption,
                     HtmlReport* r, std::string* error) {
  for (const auto& [scenario, s] : At(seg, "scenarios").items()) {
    const std::string path = At(s, "dir").get<std::string>() + "/r0/" + name;
    if (!fs::exists(path)) continue;
    std::string text = caption;
    text.replace(text.find("%s"), 2, scenario);
    if (!r->Figure(ReadText(path), text, s.value("synthetic", false), error)) return false;
  }
  return true;
}

}  // namespace

bool SegregationSection(const ReportInputs& in, int bars_figure, HtmlReport* r,
                        std::string* error) {
  const nlohmann::json& seg = At(*in.results, "segregation");
  r->Section("6. Segregation of the calibrated set");
  if (!seg.value("enabled", false)) {
    r->Paragraph("Not run: the workflow file disables the segregation stage.");
    return true;
  }
  const std::string m = in.workflow->coating.material;
  r->Paragraph("Ternary heap, " + std::to_string(At(seg, "replicates").get<int>()) +
               " replicate(s) per scenario (mean ± sem over replicates; no sem with one). The "
               "segregation fidelity and replicate count are the workflow file's; their defaults "
               "are set by what a fidelity can resolve (docs/experiments.md). A coarse heap holds "
               "few " + m + " grains, so CoV_r grows and S_n is pulled towards 1.");
  HtmlTable t{.caption = m + " (and TAED) indices per scenario",
              .header = {"scenario", "CoV 3D", "CoV_r 3D", "S_n 3D", "S_n front", "S_n back",
                         "TAED CoV 3D", "mixture angle [deg]", "discharge [s]", "replicates ok"}};
  for (const auto& [name, s] : At(seg, "scenarios").items()) {
    t.rows.push_back({name, Stat(s, m + ".cov_3d"), Stat(s, m + ".cov_r_3d"), Stat(s, m + ".s_n_3d"),
                      Stat(s, m + ".s_n_2d_front"), Stat(s, m + ".s_n_2d_back"),
                      Stat(s, "TAED.cov_3d"), Stat(s, "mixture_angle_deg"),
                      Stat(s, "discharge_time_s"), Fmt(At(s, "replicates_ok"), "%.0f")});
    t.synthetic_rows.push_back(s.value("synthetic", false));
  }
  if (!r->Table(t, error)) return false;
  if (bars_figure > 0)
    r->Paragraph("Figure " + std::to_string(bars_figure) +
                 " (at the top, with the verdict) plots " + m + "'s CoV and S_n per scenario ± sem.");
  r->Subheading("Heap front faces (replicate 0 of each scenario)");
  if (!ScenarioFigures(seg, "heap_front_r0.svg", "front face of the %s heap, coloured by species", r, error))
    return false;
  r->Subheading("Outflow composition of the funnel (Fig. 16; replicate 0 of each scenario)");
  if (!ScenarioFigures(seg, "outflow_composition_r0.svg",
                       "mass fraction per species of what left the funnel, %s (a drift would be "
                       "pre-segregation in the funnel)",
                       r, error))
    return false;
  std::vector<std::string> vtk;
  for (const auto& [name, s] : At(seg, "scenarios").items())
    for (int k = 0; k < At(seg, "replicates").get<int>(); ++k)
      vtk.push_back(At(s, "dir").get<std::string>() + "/r" + std::to_string(k) + "/heap_r0.vtk");
  r->Paragraph("VTK of each final heap (ParaView):");
  r->List(vtk);
  return true;
}

bool TailSections(const ReportInputs& in, HtmlReport* r, std::string* error) {
  (void)error;
  const nlohmann::json& f = At(*in.results, "fidelity_check");
  r->Section("7. Fidelity check");
  if (!f.value("enabled", false)) {
    r->Paragraph("Not run: " + f.value("why", std::string("disabled")));
  } else {
    r->Paragraph("The coated heap at " + Fmt(in.workflow->fidelity_check.wt_pct) +
                 " wt% with its calibrated Γ = " + Fmt(At(f, "gamma_J_m2")) + " J/m², re-run at size ×" +
                 Fmt(At(At(f, "fine_fidelity"), "size_scale")) + ", stiffness ×" +
                 Fmt(At(At(f, "fine_fidelity"), "stiffness_scale")) + ": " + Fmt(At(f, "fine_angle_deg"), "%.1f") +
                 " ± " + Fmt(At(f, "fine_sem_deg"), "%.1f") + "° against " + Fmt(At(f, "base_angle_deg"), "%.1f") +
                 " ± " + Fmt(At(f, "base_sem_deg"), "%.1f") + "° at the calibration fidelity. A shift "
                 "within the noise means the Cohesion-number scaling carries Γ between the two.");
  }
  r->Section("Where the time went");
  HtmlTable t{.header = {"stage", "wall time [s]"}};
  double total = 0;
  for (const auto& [stage, s] : in.timings->items()) {
    t.rows.push_back({stage, Fmt(s, "%.0f")});
    if (s.is_number()) total += s.get<double>();
  }
  t.rows.push_back({"all stages", Fmt(nlohmann::json(total), "%.0f")});
  if (!r->Table(t, error)) return false;
  r->Section("Output files");
  r->List({"summary.json — the paper-vs-demcal table as data",
           "report.html, report.md (+ figures/) — this report",
           "stages.jsonl — the stage journal (resume after a kill)",
           "species/<name>/, gamma_per_coating/w<level>/ — each calibration's study.json, journal, "
           "result.json, calibrated_params.json/.liggghts, evaluations.csv, plots",
           "<stage>/stage_result.json — each stage's result",
           "segregation/<scenario>/r<k>/ — each replicate's experiment outputs, heap VTK",
           "params/<scenario>.json, .liggghts — the calibrated set per scenario",
           "fidelity_check/ — the finer-fidelity heap"});
  return true;
}

}  // namespace demcal::workflow
