// The reproduce report from stand-in stage results and summary rows (no DEM run): the verdict
// comes first, verdict cells are short, a note shared by rows is printed once, no history.
#include "workflow/reproduce/reproduce_report.h"

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "outputs/html_report.h"
#include "workflow/reproduce/segregation_metrics.h"
#include "workflow/test_paths.h"

using namespace demcal::workflow;
namespace fs = std::filesystem;

namespace {

std::string ReadText(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// The report of stand-in results written into a fresh temporary folder; its HTML and Markdown.
struct WrittenReport {
  std::string html, md;
};
WrittenReport WriteStandInReport(const WorkflowFile& w, const nlohmann::json& results,
                                 const std::vector<SummaryRow>& rows,
                                 const nlohmann::json& timings, const std::string& folder) {
  const fs::path out = fs::temp_directory_path() / folder;
  fs::remove_all(out);
  fs::create_directories(out);
  const ReportInputs in{.workflow = &w, .results = &results, .rows = &rows,
                        .timings = &timings, .quick = true, .out_dir = out.string()};
  std::string error;
  REQUIRE(WriteReproduceReport(in, &error));
  WrittenReport r{ReadText(out / "report.html"), ReadText(out / "report.md")};
  fs::remove_all(out);
  return r;
}

int Count(const std::string& text, const std::string& what) {
  int n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

// Each stage's result as the stages write it, reduced to what the report reads; two coating
// levels so the Γ(w) and angle figures are drawn; segregation and the fidelity check off.
nlohmann::json StandInResults() {
  return nlohmann::json::parse(R"json({
    "species": {"species": {"EP": {"property": "rolling_friction", "value": 0.2, "sigma": 0.02,
                                   "measured": 31, "uncertainty": 1, "simulated": 31.4,
                                   "sem": 0.3, "termination": "within_noise"}}},
    "cohesion": {"convention": "R* = R", "cohesion_number": 1.64e-3, "gamma_sim_J_m2": 0.0409,
                 "explanation": "Γ ∝ E^(2/5)", "inputs": {"gamma_J_m2": 0.086}},
    "gamma_per_coating": {"start_gamma_J_m2": 0.0409, "levels": [
      {"wt_pct": 0.5, "value": 0.05, "sigma": 0.01, "measured": 37.6, "uncertainty": 1,
       "simulated": 37.2, "sem": 0.4, "synthetic": false, "provenance": "measured"},
      {"wt_pct": 2.5, "value": 0.24, "sigma": 0.03, "measured": 45.0, "uncertainty": 1,
       "simulated": 44.6, "sem": 0.5, "synthetic": true, "provenance": "synthetic"}]},
    "gamma_curve": {"fitted": false, "why": "stand-in", "synthetic": true},
    "dissimilar_pairs": {"from": "stand-in", "synthetic": true, "pairs": []},
    "segregation": {"enabled": false},
    "fidelity_check": {"enabled": false, "why": "off in this stand-in"}})json");
}

}  // namespace

TEST_CASE("reproduce report: verdict first, short verdicts, each note once", "[unit]") {
  const fs::path root = demcal::testing::RepoRoot();
  WorkflowFile w;
  std::string error;
  REQUIRE(LoadWorkflowFile((root / "datasets/alizadeh2018/workflow.json").string(), &w, &error));
  // The values as the stages would give them at a short run: the clump counts share the long
  // shape note (stage_species.cc), the segregation rows were not run.
  const std::string shape_note = "shape fixed by the workflow file: " + w.shape_assumption;
  DemcalValues v;
  v["angle_EP_deg"] = {.mean = 31.4, .sem = 0.3, .note = "calibrated to it (rolling_friction)"};
  for (const char* s : {"BP", "TAED", "EP"})
    v[std::string("clump_count_") + s] = {.note = shape_note};
  v["coh_coated_EP"] = {.mean = 1.64e-3};
  v["gamma_sim_J_m2"] = {.mean = 0.0409, .note = "Γ ∝ E^(2/5) at constant Coh"};
  v["gamma_w2.5_J_m2"] = {.mean = 0.24, .sem = 0.03, .synthetic = true};
  const std::vector<SummaryRow> rows = BuildSummaryRows(w.reference, v);
  const nlohmann::json results = StandInResults();
  const nlohmann::json timings = {{"species", 60.0}, {"cohesion", 0.0}};
  const WrittenReport report = WriteStandInReport(w, results, rows, timings, "demcal_reproduce_report_test");
  const std::string& html = report.html;
  const std::string& md = report.md;

  // The headline and the key figures come before the table; the notes after it.
  const size_t headline = html.find("<ul class=\"headline\">");
  const size_t first_table = html.find("<table>");
  REQUIRE(headline != std::string::npos);
  CHECK(headline < first_table);
  CHECK(html.find("<strong>Matched the paper:</strong>") < first_table);
  CHECK(html.find("<strong>Not run:</strong> BP clump sphere count; TAED clump sphere count; EP "
                  "clump sphere count<sup") != std::string::npos);
  CHECK(Count(html.substr(0, first_table), "<figure") == 2);  // Γ(w) and the angle figure
  CHECK(first_table < html.find("<ol class=\"notes\">"));

  // The 90-word shape note: once as a footnote, not in the headline or any cell.
  CHECK(Count(html, HtmlEscape(shape_note)) == 1);
  CHECK(Count(md, shape_note) == 1);
  // Every tone (verdict) cell is short: the text before its footnote mark.
  int verdict_cells = 0;
  for (size_t at = html.find("<td class=\"tone-"); at != std::string::npos;
       at = html.find("<td class=\"tone-", at + 1)) {
    const size_t text = html.find('>', at) + 1;
    const size_t end = std::min(html.find("</td>", text), html.find("<sup", text));
    CHECK(end - text < 60);
    ++verdict_cells;
  }
  CHECK(verdict_cells == static_cast<int>(rows.size()));

  // No history in what a reader sees.
  CHECK(html.find("issue ") == std::string::npos);
  CHECK(md.find("issue ") == std::string::npos);

  // The Markdown twin reads in the same order.
  const size_t md_headline = md.find("- **Matched the paper:**");
  const size_t md_figure = md.find("![Figure 1](figures/figure_01.svg)");
  const size_t md_table = md.find("| quantity | paper |");
  const size_t md_notes = md.find("\n1. ");
  REQUIRE(md_headline != std::string::npos);
  CHECK(md_headline < md_figure);
  CHECK(md_figure < md_table);
  CHECK(md_table < md_notes);
}

TEST_CASE("reproduce report: the Fig. 3 clump-count table and the mechanism rows", "[unit]") {
  const fs::path root = demcal::testing::RepoRoot();
  WorkflowFile w;
  std::string error;
  REQUIRE(LoadWorkflowFile((root / "datasets/alizadeh2018/workflow_clumps.json").string(), &w,
                           &error));
  for (const WorkflowSpecies& s : w.species) {  // the paper's shape calibration: μr held
    CHECK(s.hold);
    CHECK(s.clump_counts.back() == (s.name == "EP" ? 3 : 5));
  }
  nlohmann::json results = StandInResults();
  results["species"]["species"]["EP"]["clump_count"] = 3;
  results["species"]["species"]["EP"]["clump_note"] = "chose 3, the smallest count that matches";
  results["species"]["species"]["EP"]["clump_table"] = nlohmann::json::parse(R"json([
    {"count": 1, "angle_deg": 26.04, "angle_sem_deg": 0.51, "cost": 24.3, "within_noise": false,
     "agrees": false, "termination": "budget"},
    {"count": 2, "angle_deg": 28.7, "angle_sem_deg": null, "cost": null, "within_noise": false,
     "agrees": false, "termination": "failed"},
    {"count": 3, "angle_deg": 30.66, "angle_sem_deg": 0.42, "cost": 0.31, "within_noise": true,
     "agrees": true, "termination": "within_noise"}])json");
  DemcalValues v;
  v["clump_count_EP"] = {.mean = 3};
  v["ep_landing_depth_uncoated_m"] = {.mean = 4.2e-4, .sem = 1e-4};
  v["ep_bp_contacts_per_grain_coated"] = {.mean = 9.2, .sem = 0.4};
  const std::vector<SummaryRow> rows = BuildSummaryRows(w.reference, v);
  int mechanism_rows = 0;
  for (const SummaryRow& row : rows)
    mechanism_rows += row.key.starts_with("ep_landing_depth_") ||
                      row.key.starts_with("ep_after_impact_specific_kinetic_") ||
                      row.key.starts_with("ep_bp_contacts_per_grain_");
  CHECK(mechanism_rows == 9);  // three observables × uncoated, coated, excessive
  const nlohmann::json timings = {{"species", 60.0}};
  const WrittenReport report = WriteStandInReport(w, results, rows, timings, "demcal_reproduce_report_clumps_test");
  const std::string& html = report.html;
  const std::string& md = report.md;
  // The Fig. 3 table: after the species table, one row per count, angle ± sem, cost, verdict.
  const size_t fig3 = html.find("EP: clump sphere count against the measured angle");
  REQUIRE(fig3 != std::string::npos);
  CHECK(html.find("1. Species") < fig3);
  CHECK(html.find("<td>26.0 ± 0.5</td>", fig3) != std::string::npos);
  CHECK(html.find("<td>28.7</td>", fig3) != std::string::npos);  // no sem: no ±
  CHECK(html.find("<td>30.7 ± 0.4</td>", fig3) != std::string::npos);
  CHECK(html.find("<td>24.3</td>", fig3) != std::string::npos);
  CHECK(html.find("EP: chose 3, the smallest count that matches.", fig3) != std::string::npos);
  CHECK(md.find("| spheres | angle demcal [deg] | cost (Σ z²) |") != std::string::npos);
  // The mechanism rows, in the summary table with their units.
  CHECK(html.find("tracked EP: depth below the heap surface at first rest after impact, "
                  "uncoated [m]") != std::string::npos);
  CHECK(html.find("0.00042 ± 0.0001") != std::string::npos);
  CHECK(html.find("BP grains touching each EP grain in the heap, 2.5 wt% [-]") !=
        std::string::npos);
}

TEST_CASE("reproduce report: the Fig. 3 table with the calibrated aspect ratio per count",
          "[unit]") {
  const fs::path root = demcal::testing::RepoRoot();
  WorkflowFile w;
  std::string error;
  REQUIRE(LoadWorkflowFile((root / "datasets/alizadeh2018/workflow_clumps.json").string(), &w,
                           &error));
  nlohmann::json results = StandInResults();
  nlohmann::json& ep = results["species"]["species"]["EP"];
  ep["clump_count"] = 0;
  ep["clump_note"] = "no count matched the measured angle within noise";
  ep["clump_table"] = nlohmann::json::parse(R"json([
    {"count": 1, "aspect_ratio": 1, "aspect_ratio_sigma": null, "aspect_at_bound": false,
     "angle_deg": 24.1, "angle_sem_deg": 0.6, "cost": 253.0, "within_noise": false,
     "agrees": false, "termination": "budget", "note": "", "heaps": 2, "wall_time_s": 40},
    {"count": 2, "aspect_ratio": 2.0, "aspect_ratio_sigma": 0.21, "aspect_at_bound": true,
     "angle_deg": 33.2, "angle_sem_deg": 0.7, "cost": 46.2, "within_noise": false,
     "agrees": false, "termination": "out_of_reach",
     "note": "best aspect ratio at a bound (upper bound 2: ...), still not within noise",
     "heaps": 6,
     "wall_time_s": 130},
    {"count": 3, "aspect_ratio": 2.825, "aspect_ratio_sigma": 0.009, "aspect_at_bound": false,
     "angle_deg": 31.0, "angle_sem_deg": 0.74, "cost": 0.0, "within_noise": true,
     "local_fit": true, "agrees": true, "termination": "budget",
     "note": "aspect ratio matched within noise by a straight line through the 6 candidates",
     "heaps": 28, "wall_time_s": 120}])json");
  // A Γ level whose value is the line through its candidates (no single one matched).
  results["gamma_per_coating"]["levels"][1]["termination"] = "budget";
  results["gamma_per_coating"]["levels"][1]["by_line"] = true;
  DemcalValues v;
  v["aspect_ratio_EP"] = {.mean = 2.0, .sem = 0.21};
  const std::vector<SummaryRow> rows = BuildSummaryRows(w.reference, v);
  const WrittenReport report =
      WriteStandInReport(w, results, rows, {{"species", 60.0}}, "demcal_reproduce_report_aspect");
  const std::string& html = report.html;
  const size_t fig3 = html.find("EP: clump sphere count and calibrated aspect ratio against the "
                                "measured angle");
  REQUIRE(fig3 != std::string::npos);
  CHECK(html.find("<td>1 (sphere)</td>", fig3) != std::string::npos);
  CHECK(html.find("<td>2.00 ± 0.21 (at bound)</td>", fig3) != std::string::npos);
  CHECK(html.find("<td>33.2 ± 0.7</td>", fig3) != std::string::npos);
  CHECK(html.find("<td>46.2</td>", fig3) != std::string::npos);
  CHECK(html.find("best aspect ratio at a bound (upper bound 2", fig3) !=
        std::string::npos);
  // A count matched by the line through its candidates says so beside its aspect ratio.
  CHECK(html.find("<td>2.83 ± 0.01 (line)</td>", fig3) != std::string::npos);
  CHECK(html.find("matched within noise by a straight line", fig3) != std::string::npos);
  CHECK(report.md.find("| spheres | aspect ratio a/c [-] | angle demcal [deg] | cost (Σ z²) | "
                       "within noise | heaps | wall [s] |") != std::string::npos);
  CHECK(html.find("<td>budget; value: the line through the candidates around the crossing</td>") !=
        std::string::npos);
  // The paper states no aspect ratio: the summary row is demcal's alone.
  CHECK(html.find("EP clump aspect ratio a/c (calibrated; the paper gives none)") !=
        std::string::npos);
}

TEST_CASE("reproduce report: a coarse heap's mixture angle carries its note once", "[unit]") {
  const fs::path root = demcal::testing::RepoRoot();
  WorkflowFile w;
  std::string error;
  REQUIRE(LoadWorkflowFile((root / "datasets/alizadeh2018/workflow.json").string(), &w, &error));
  // Two heaps at size ×5, as the segregation stage summarises them.
  const nlohmann::json scenario = {{"mixture_angle_deg", {{"mean", 48.2}, {"sem", 0.5}, {"n", 2}}},
                                   {"size_scale", {{"mean", 5.0}, {"sem", 0.0}, {"n", 2}}}};
  const nlohmann::json values =
      SegregationSummaryValues({{"uncoated", scenario}, {"coated", scenario}}, "EP");
  DemcalValues v;
  for (const char* key : {"mixture_angle_uncoated_deg", "mixture_angle_coated_deg"}) {
    const nlohmann::json& x = values[key];
    v[key] = {.mean = x["mean"].get<double>(), .sem = x["sem"].get<double>(),
              .note = x["note"].get<std::string>()};
  }
  const std::string note = v["mixture_angle_uncoated_deg"].note;
  REQUIRE(note.find("not like for like") == 0);
  const std::vector<SummaryRow> rows = BuildSummaryRows(w.reference, v);
  const WrittenReport report = WriteStandInReport(w, StandInResults(), rows, {{"species", 60.0}},
                                                  "demcal_reproduce_report_angle_note_test");
  // Both mixture-angle rows point at one footnote with the measured figures and the document.
  CHECK(Count(report.html, HtmlEscape(note)) == 1);
  CHECK(Count(report.md, note) == 1);
  CHECK(note.find("13.7 ± 0.4°") != std::string::npos);
  CHECK(note.find("docs/experiments/segregation_angle.md") != std::string::npos);
  // The rows are still compared with the paper (the verdict cell says by how much).
  for (const SummaryRow& r : rows)
    if (r.key == "mixture_angle_uncoated_deg") CHECK(r.kind == VerdictKind::kDiffers);
}
