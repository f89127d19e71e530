// The whole of `demcal reproduce alizadeh2018 --quick` (minutes on the DEM: [.][long], run by
// scripts/run_long_tests.sh): the report's structure, summary.json's rows, and the stage
// journal's resume after the journal is cut back as a kill would leave it.
#include <catch2/catch.hpp>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "workflow/reproduce/run_reproduce.h"
#include "workflow/reproduce/workflow_file.h"
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
int Count(const std::string& text, const std::string& what) {
  int n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}
}  // namespace

TEST_CASE("reproduce alizadeh2018 --quick runs end to end and resumes from its journal",
          "[.][long]") {
  const fs::path root = demcal::testing::RepoRoot();
  const fs::path out = fs::temp_directory_path() / "demcal_reproduce_quick_long";
  fs::remove_all(out);
  ReproduceOptions options{.workflow = "alizadeh2018", .out_dir = out.string(), .quick = true,
                           .repo_root = root.string()};
  std::ostringstream log;
  REQUIRE(RunReproduce(options, log) == 0);
  INFO(log.str());

  // summary.json: one row per reference number of the workflow file, each with a verdict.
  WorkflowFile w;
  std::string error;
  REQUIRE(LoadWorkflowFile((root / "datasets/alizadeh2018/workflow.json").string(), &w, &error));
  const nlohmann::json summary = nlohmann::json::parse(ReadText(out / "summary.json"));
  REQUIRE(summary["rows"].size() == w.reference.size());
  for (const auto& row : summary["rows"]) CHECK_FALSE(row["verdict"].get<std::string>().empty());
  // The Cohesion number is arithmetic: always computed, and the paper's 1.6e-3 within rounding.
  CHECK(summary["rows"][6]["key"] == "coh_coated_EP");
  CHECK(summary["rows"][6]["demcal_mean"].get<double>() == Approx(1.6e-3).margin(0.05e-3));

  // The report: every stage's section, figures inline, synthetic badges, no external images.
  const std::string html = ReadText(out / "report.html");
  for (const char* section : {"1. Species", "2. Cohesion number", "3. Γ per coating level",
                              "4. Γ(w) curve", "5. Dissimilar pairs",
                              "6. Segregation of the calibrated set", "7. Fidelity check"})
    CHECK(html.find(section) != std::string::npos);
  CHECK(Count(html, "<figure") >= 3);
  CHECK(Count(html, ">synthetic<") >= 1);
  CHECK(html.find("<img") == std::string::npos);
  CHECK(fs::exists(out / "report.md"));
  CHECK(fs::exists(out / "params" / "coated.json"));
  CHECK(fs::exists(out / "params" / "coated.liggghts"));
  CHECK(fs::exists(out / "segregation" / "uncoated" / "r0" / "heap_r0.vtk"));

  // Resume: drop the records of the stages from the curve on (keeping the finished segregation
  // replicate runs) and cut the last line short, as a kill during the segregation stage leaves it;
  // run again: the first three stages and every replicate run are read back, not repeated, and
  // the summary is the same.
  std::ifstream in(out / "stages.jsonl");
  std::string line, kept;
  int replicate_records = 0;
  while (std::getline(in, line)) {
    const bool stage_after = line.find("\"key\":\"gamma_curve\"") != std::string::npos ||
                             line.find("\"key\":\"dissimilar_pairs\"") != std::string::npos ||
                             line.find("\"key\":\"segregation\"") != std::string::npos ||
                             line.find("\"key\":\"fidelity_check\"") != std::string::npos;
    replicate_records += line.find("\"key\":\"segregation/") != std::string::npos;
    if (!stage_after) kept += line + "\n";
  }
  in.close();
  REQUIRE(replicate_records == 3);  // uncoated, coated, excessive; one replicate each at --quick
  std::ofstream(out / "stages.jsonl") << kept << "{\"key\": \"gamma_cu";  // cut mid-line
  std::ostringstream again;
  REQUIRE(RunReproduce(options, again) == 0);
  CHECK(Count(again.str(), ": from the journal") == 3);
  CHECK(again.str().find("3 scenarios x 1 replicates, 3 from the journal") != std::string::npos);
  const nlohmann::json resumed = nlohmann::json::parse(ReadText(out / "summary.json"));
  CHECK(resumed["rows"] == summary["rows"]);

  // The report opens in a real browser, every figure laid out, no console errors.
  const std::string check = "python3 " + (root / "scripts/check_html_report.py").string() + " " +
                            (out / "report.html").string() + " --min-figures 3";
  const int status = std::system(check.c_str());
  CHECK((WEXITSTATUS(status) == 0 || WEXITSTATUS(status) == 77));
}
