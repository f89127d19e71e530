// journal-stats on hand-made journals with known times: two worker ranks of an MPI job in one
// journal, a threaded run in another (diagnose's journal/<hash>.jsonl), an older record without
// times, and a .jsonl that is not a journal.
#include "workflow/journal_stats/journal_stats.h"

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "apps/command_line.h"
#include "apps/journal_stats_command.h"
#include "core/io/scratch_dir.h"

using namespace demcal::workflow;

namespace {

std::string Record(const char* host, int rank, double start, double end, double batch) {
  static int seed = 0;
  nlohmann::json j{{"group", "g"}, {"parameters", {0.5}}, {"replicate", 0}, {"seed", ++seed},
                   {"status", "ok"}, {"values", {{"angle_deg", 30}}}, {"wall_time_s", end - start},
                   {"host", host}, {"rank", rank}, {"start_unix_s", start},
                   {"end_unix_s", end}, {"batch_unix_s", batch}};
  return j.dump() + "\n";
}

constexpr const char* kHeader = R"({"format": "demcal-journal/3", "study": "f"})";

void WriteJob(const demcal::testing::ScratchDir& dir) {
  std::filesystem::create_directories(dir.str("journal"));
  std::ofstream(dir.str("journal.jsonl"))
      << kHeader << "\n"
      << Record("a", 1, 100, 104, 100) << Record("a", 1, 104, 106, 100)
      << Record("a", 2, 100, 103, 100) << Record("a", 1, 110, 113, 108)
      << Record("a", 2, 110, 112, 108)
      << R"({"parameters": [0.7], "replicate": 0, "seed": 1, "status": "ok", "value": 31.0, )"
      << R"("wall_time_s": 2.5})" << "\n";
  // Two runs side by side on one rank (--threads 2): busy 5 s of the span, 7 s of runs.
  std::ofstream(dir.str("journal/0123abcd.jsonl"))
      << kHeader << "\n" << Record("b", 0, 100, 105, 100) << Record("b", 0, 101, 103, 100);
  std::ofstream(dir.str("stages.jsonl")) << R"({"format": "demcal-stages/1"})" << "\n";
}

}  // namespace

TEST_CASE("journal-stats: busy fractions, run times and the critical path of a known job",
          "[unit][workflow]") {
  demcal::testing::ScratchDir dir("journal_stats");
  WriteJob(dir);
  JournalStats s;
  std::string error;
  REQUIRE(ReadJournalStats(dir.str(), &s, &error));
  CHECK(s.journals == 2);
  CHECK(s.simulations == 8);
  CHECK(s.untimed == 1);
  CHECK(s.run_time_s == Approx(4 + 2 + 3 + 3 + 2 + 2.5 + 5 + 2));
  CHECK(s.mean_run_time_s == Approx(23.5 / 8));
  CHECK(s.wall_span_s == Approx(13));  // 100 .. 113
  CHECK(s.runs_at_once == Approx(21.0 / 13));
  // Batch 100 of both journals (one farm batch, as calibrations run together share it: longest
  // 5 s) and batch 108 of the first (3 s).
  CHECK(s.batches == 2);
  CHECK(s.critical_path_s == Approx(5 + 3));
  REQUIRE(s.ranks.size() == 3);
  CHECK(s.ranks[0].host == "a");
  CHECK(s.ranks[0].rank == 1);
  CHECK(s.ranks[0].runs == 3);
  CHECK(s.ranks[0].busy_fraction == Approx(9.0 / 13));
  CHECK(s.ranks[1].rank == 2);
  CHECK(s.ranks[1].busy_fraction == Approx(5.0 / 13));
  CHECK(s.ranks[2].host == "b");
  CHECK(s.ranks[2].busy_fraction == Approx(5.0 / 13));  // the union of [100, 105] and [101, 103]
  CHECK(s.ranks[2].runs_at_once == Approx(7.0 / 13));
}

TEST_CASE("demcal journal-stats prints lines or JSON and refuses a folder without journals",
          "[unit][cli]") {
  using demcal::testing::RunCli;
  demcal::testing::ScratchDir dir("journal_stats_cli");
  WriteJob(dir);
  const auto text = RunCli(demcal::apps::AddJournalStatsCommand, {"journal-stats", dir.str()});
  CHECK(text.exit_code == kExitOk);
  CHECK_THAT(text.out, Catch::Contains("simulations: 8 (1 without host, rank and times)"));
  CHECK_THAT(text.out, Catch::Contains("wall span (s): 13"));
  CHECK_THAT(text.out, Catch::Contains("rank 2 on a: 2 runs"));
  const auto json =
      RunCli(demcal::apps::AddJournalStatsCommand, {"journal-stats", dir.str(), "--json"});
  REQUIRE(json.exit_code == kExitOk);
  const nlohmann::json j = nlohmann::json::parse(json.out);
  CHECK(j["format"] == "demcal-journal-stats/1");
  CHECK(j["critical_path_s"].get<double>() == Approx(5 + 3));
  CHECK(j["ranks"][1]["busy_fraction"].get<double>() == Approx(5.0 / 13));
  demcal::testing::ScratchDir empty("journal_stats_empty");
  const auto none = RunCli(demcal::apps::AddJournalStatsCommand, {"journal-stats", empty.str()});
  CHECK(none.exit_code == kExitInvalidInput);
  CHECK_THAT(none.err, Catch::Contains("no evaluation journal"));
}
