// The wall-time model (workflow/journal_stats/wall_time_model.h) on a hand-made job whose answer
// is worked out by hand: list scheduling of each batch's measured runs in queue order, batches
// in sequence, the measured time between batches added at every rank count.
#include "workflow/journal_stats/wall_time_model.h"

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "apps/command_line.h"
#include "apps/journal_stats_command.h"
#include "core/io/scratch_dir.h"

using namespace demcal::workflow;

namespace {

std::string Record(int rank, double start, double end, double batch) {
  static int seed = 0;
  nlohmann::json j{{"group", "g"},         {"parameters", {0.5}}, {"replicate", 0},
                   {"seed", ++seed},       {"status", "ok"},      {"wall_time_s", end - start},
                   {"host", "a"},          {"rank", rank},        {"start_unix_s", start},
                   {"end_unix_s", end},    {"batch_unix_s", batch}};
  return j.dump() + "\n";
}

std::string StageRun(const char* key, double start, double end) {
  nlohmann::json run{{"host", "a"}, {"rank", 1}, {"start_unix_s", start}, {"end_unix_s", end},
                     {"batch_unix_s", 120}};
  return nlohmann::json{{"key", key}, {"result", {{"ok", true}, {"run", run}}}}.dump() + "\n";
}

// A calibration journal: batch 100 ran 4, 2, 3 and 1 s runs on two slots (spanning 100..105.5),
// batch 110 one 6 s run (110..116). Reproduce's stage journal: a stage record (not a run) and
// two segregation runs of 3 and 2 s in batch 120 (120..123). Span 100..123 = 23 s, batches cover
// 5.5 + 6 + 3 = 14.5 s, so 8.5 s lie between batches.
void WriteJob(const demcal::testing::ScratchDir& dir) {
  std::ofstream(dir.str("journal.jsonl"))
      << R"({"format": "demcal-journal/3", "study": "f"})" << "\n"
      << Record(1, 100, 104, 100) << Record(2, 100.5, 102.5, 100) << Record(2, 102.5, 105.5, 100)
      << Record(1, 104, 105, 100) << Record(1, 110, 116, 110);
  std::ofstream(dir.str("stages.jsonl"))
      << R"({"format": "demcal-stage-journal/1", "workflow": "w/quick"})" << "\n"
      << R"({"key": "species", "result": {"values": {}}})" << "\n"
      << StageRun("segregation/uncoated/r0", 120, 123)
      << StageRun("segregation/uncoated/r1", 120, 122);
}

}  // namespace

TEST_CASE("list scheduling hands each run to the first free slot, in queue order",
          "[unit][workflow]") {
  CHECK(ListScheduleMakespan({}, 4) == 0);
  CHECK(ListScheduleMakespan({5, 3, 3, 3}, 1) == Approx(14));
  // Slot 0 takes 5 (0..5), slot 1 takes 3 (0..3) and the next 3 (3..6), slot 0 the last (5..8).
  CHECK(ListScheduleMakespan({5, 3, 3, 3}, 2) == Approx(8));
  // Queue order matters: the long run last leaves the other slot idle.
  CHECK(ListScheduleMakespan({1, 1, 6}, 2) == Approx(7));
  CHECK(ListScheduleMakespan({6, 1, 1}, 2) == Approx(6));
  CHECK(ListScheduleMakespan({5, 3, 3, 3}, 10) == Approx(5));  // more slots than runs
}

TEST_CASE("wall-time model of a hand-made job at 1, 2, 3 and 5 ranks", "[unit][workflow]") {
  demcal::testing::ScratchDir dir("wall_time_model");
  WriteJob(dir);
  std::vector<JournalRun> runs;
  int journals = 0;
  std::string error;
  REQUIRE(ReadJournalRuns(dir.str(), &runs, &journals, &error));
  CHECK(journals == 2);
  const WallTimeModel m = ModelWallTime(runs, {1, 2, 3, 5});
  CHECK(m.runs == 7);
  CHECK(m.batches == 3);
  CHECK(m.measured_span_s == Approx(23));
  CHECK(m.between_batches_s == Approx(8.5));
  CHECK(m.run_time_s == Approx(4 + 2 + 3 + 1 + 6 + 3 + 2));
  REQUIRE(m.predictions.size() == 4);
  // 1 rank (no mpirun, one run at a time) and 2 ranks (one worker): every run in sequence.
  CHECK(m.predictions[0].slots == 1);
  CHECK(m.predictions[0].wall_span_s == Approx(10 + 6 + 5 + 8.5));
  CHECK(m.predictions[1].slots == 1);
  CHECK(m.predictions[1].wall_span_s == Approx(29.5));
  // 3 ranks, 2 slots: batch 100 in queue order 4, 2, 3, 1: slot A 4 then 1 (5), slot B 2 then
  // 3 (5); batch 110: 6; batch 120: 3 and 2 side by side (3).
  CHECK(m.predictions[2].slots == 2);
  CHECK(m.predictions[2].wall_span_s == Approx(5 + 6 + 3 + 8.5));
  // 5 ranks, 4 slots: each batch its longest run.
  CHECK(m.predictions[3].wall_span_s == Approx(4 + 6 + 3 + 8.5));
}

TEST_CASE("wall-time model: calibrations run together share a batch across their journals",
          "[unit][workflow]") {
  // Two calibrations' journals, one farm batch (farm::RunGathered): 4 and 2 s runs in one,
  // a 3 s run started at 202 in the other. Queue order by start: 2, 4 (both at 200), then 3.
  demcal::testing::ScratchDir dir("wall_time_model_gathered");
  std::filesystem::create_directories(dir.str("a"));
  std::filesystem::create_directories(dir.str("b"));
  const char* header = R"({"format": "demcal-journal/3", "study": "f"})";
  std::ofstream(dir.str("a/journal.jsonl"))
      << header << "\n" << Record(1, 200, 204, 200) << Record(2, 200, 202, 200);
  std::ofstream(dir.str("b/journal.jsonl")) << header << "\n" << Record(2, 202, 205, 200);
  std::vector<JournalRun> runs;
  int journals = 0;
  std::string error;
  REQUIRE(ReadJournalRuns(dir.str(), &runs, &journals, &error));
  CHECK(journals == 2);
  const WallTimeModel m = ModelWallTime(runs, {1, 3, 5});
  CHECK(m.batches == 1);
  CHECK(m.between_batches_s == Approx(0));
  CHECK(m.predictions[0].wall_span_s == Approx(9));  // one at a time
  CHECK(m.predictions[1].wall_span_s == Approx(5));  // 2 then 3 on one slot, 4 on the other
  CHECK(m.predictions[2].wall_span_s == Approx(4));  // each run a slot: the longest
}

TEST_CASE("demcal journal-stats --model-ranks prints the prediction and refuses 0 ranks",
          "[unit][cli]") {
  using demcal::testing::RunCli;
  demcal::testing::ScratchDir dir("wall_time_model_cli");
  WriteJob(dir);
  const auto text = RunCli(demcal::apps::AddJournalStatsCommand,
                           {"journal-stats", dir.str(), "--model-ranks", "3,5"});
  REQUIRE(text.exit_code == kExitOk);
  CHECK_THAT(text.out, Catch::Contains("predicted wall span at 3 ranks (2 runs at once) (s): 22.5"));
  const auto json = RunCli(demcal::apps::AddJournalStatsCommand,
                           {"journal-stats", dir.str(), "--model-ranks", "5", "--json"});
  REQUIRE(json.exit_code == kExitOk);
  const nlohmann::json j = nlohmann::json::parse(json.out);
  CHECK(j["wall_time_model"]["predictions"][0]["wall_span_s"].get<double>() == Approx(21.5));
  const auto zero = RunCli(demcal::apps::AddJournalStatsCommand,
                           {"journal-stats", dir.str(), "--model-ranks", "0"});
  CHECK(zero.exit_code == kExitInvalidInput);
}
