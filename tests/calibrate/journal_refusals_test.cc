// A journal line that demcal would not have written is refused on loading, naming the line,
// rather than counted as a finished run (an unknown observable, a status no run ends with, a
// seed the study never gives); and a journal that cannot be written stops the work instead of
// letting it go on unjournalled. The full disk is a file size limit (RLIMIT_FSIZE with SIGXFSZ
// ignored): write() then stores what fits and fails with EFBIG, as a full disk fails with
// ENOSPC, with no special file system needed.
#include <signal.h>
#include <sys/resource.h>

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>

#include "calibrate/calibration.h"
#include "calibrate/evaluation_journal.h"
#include "calibrate/target_evaluator.h"
#include "core/io/scratch_dir.h"
#include "objectives/common/replicates.h"
#include "synthetic_observable.h"

using namespace demcal::calibrate;
using demcal::calibrate::testing::OneMaterialModel;
using demcal::calibrate::testing::SyntheticAngle;

namespace {

const std::string kHeader = R"({"format": "demcal-journal/3", "study": "f"})";

std::string Load(const std::string& path, const std::string& records, uint64_t* seeds = nullptr) {
  std::ofstream(path, std::ios::trunc) << kHeader << "\n" << records << "\n";
  EvaluationJournal j;
  if (seeds) j.ExpectSeeds(*seeds);
  std::string error;
  return j.Open(path, "f", &error) ? "" : error;
}

// Every write of this process limited to files of `bytes`; lifted when it goes out of scope.
class FileSizeLimit {
 public:
  explicit FileSizeLimit(rlim_t bytes) {
    getrlimit(RLIMIT_FSIZE, &saved_);
    old_handler_ = signal(SIGXFSZ, SIG_IGN);
    rlimit limit = saved_;
    limit.rlim_cur = bytes;
    setrlimit(RLIMIT_FSIZE, &limit);
  }
  ~FileSizeLimit() {
    setrlimit(RLIMIT_FSIZE, &saved_);
    signal(SIGXFSZ, old_handler_);
  }

 private:
  rlimit saved_{};
  sighandler_t old_handler_;
};

ParameterSpace RollingSpace() {
  ParameterSpace space;
  space.parameters.push_back({"mu_r", PairProperty::kRollingFriction, 0, 0, 0.02, 0.9, 0.3});
  return space;
}

}  // namespace

TEST_CASE("journal: a record naming an unknown observable is refused, naming the line",
          "[unit][calibrate]") {
  demcal::testing::ScratchDir dir("journal_unknown_observable");
  const std::string path = dir.str("journal.jsonl");
  const std::string good = R"({"group": "g", "parameters": [0.5], "replicate": 0, "seed": 1, )"
                           R"("status": "ok", "values": {"angle_deg": 30}})";
  CHECK(Load(path, good).empty());
  const std::string error =
      Load(path, good + "\n" + R"({"group": "g", "parameters": [0.5], "replicate": 1, "seed": 2, )"
                                R"("status": "ok", "values": {"angel_deg": 30}})");
  CHECK_THAT(error, Catch::StartsWith(path + ":3: values.angel_deg: not an observable demcal "
                                             "measures (angle_deg, "));
}

TEST_CASE("journal: a status no run ends with is refused with the allowed ones",
          "[unit][calibrate]") {
  demcal::testing::ScratchDir dir("journal_status");
  const std::string path = dir.str("journal.jsonl");
  const std::string error = Load(
      path, R"({"parameters": [0.5], "replicate": 0, "seed": 1, "status": "weird", "value": 3})");
  CHECK_THAT(error, Catch::Contains(path + ":2: status: 'weird' is not a status demcal writes"));
  CHECK_THAT(error, Catch::Contains("not_settled"));
  CHECK_THAT(error, Catch::Contains("non_finite"));
  CHECK(Load(path, R"({"parameters": [0.5], "replicate": 0, "seed": 1, )"
                   R"("status": "not_settled", "value": null})").empty());
}

TEST_CASE("journal: a record with another seed than the study gives is refused on loading",
          "[unit][calibrate]") {
  demcal::testing::ScratchDir dir("journal_seed");
  const std::string path = dir.str("journal.jsonl");
  uint64_t base = 7;
  const uint64_t right = demcal::objectives::ReplicateSeed(base, 1);
  auto record = [](uint64_t seed) {
    return R"({"parameters": [0.5], "replicate": 1, "seed": )" + std::to_string(seed) +
           R"(, "status": "ok", "value": 30})";
  };
  CHECK(Load(path, record(right), &base).empty());
  CHECK(Load(path, record(right + 1)).empty());  // without ExpectSeeds: not checked
  CHECK(Load(path, record(right + 1), &base) ==
        path + ":2: seed: " + std::to_string(right + 1) + " is not the seed of replicate 1 in " +
            "this study (" + std::to_string(right) + "); the journal has been edited or mixed");
}

TEST_CASE("journal: a full disk at the header or an append is an I/O error, and leaves no half "
          "record", "[unit][calibrate]") {
  demcal::testing::ScratchDir dir("journal_full_disk");
  const std::string path = dir.str("journal.jsonl");
  std::string error;
  {
    EvaluationJournal j;
    FileSizeLimit full(0);
    CHECK_FALSE(j.Open(path, "f", &error));
    CHECK(j.io_error());
    CHECK_THAT(error, Catch::Contains("cannot write: File too large"));
  }
  std::filesystem::remove(path);
  EvaluationJournal j;
  REQUIRE(j.Open(path, "f", &error));
  REQUIRE(j.Append({{0.5}, 0, 1, "ok", 30.0, 1.0}, &error));
  const auto whole = std::filesystem::file_size(path);
  {
    FileSizeLimit full(whole + 20);  // room for 20 bytes of the next record, not all of it
    CHECK_FALSE(j.Append({{0.6}, 0, 1, "ok", 31.0, 1.0}, &error));
  }
  CHECK(std::filesystem::file_size(path) == whole);  // the 20 bytes were cut back
  CHECK_FALSE(j.Append({{0.7}, 0, 1, "ok", 32.0, 1.0}, &error));  // and it stays failed
  CHECK_THAT(error, Catch::Contains("cannot write"));
  EvaluationJournal reopened;
  REQUIRE(reopened.Open(path, "f", &error));
  CHECK(reopened.LoadedRecords() == 1);
}

TEST_CASE("journal: once a record cannot be written, the calibration runs nothing more",
          "[unit][calibrate]") {
  demcal::testing::ScratchDir dir("journal_full_disk_calibration");
  const std::string path = dir.str("journal.jsonl");
  std::string error;
  EvaluationJournal journal;
  REQUIRE(journal.Open(path, "f", &error));
  SyntheticAngle angle;
  const ParameterSpace space = RollingSpace();
  std::vector<RunGroup> groups{{"g", &angle, OneMaterialModel(), space, {}, {}}};
  TargetEvaluator evaluator(space, groups, {{0, "angle_deg"}}, {.replicates = 2, .seed = 5},
                            &journal);
  CalibrationOptions options;
  options.optimiser_options.max_evaluations = 6;
  CalibrationSummary s;
  {
    FileSizeLimit full(std::filesystem::file_size(path));  // the header fits, no record does
    s = Calibrate(evaluator, space, {{"angle", "angle_deg", 38.0, 0.5, "synthetic"}}, options);
  }
  CHECK_THAT(s.journal_error, Catch::Contains(path + ": cannot write"));
  CHECK(angle.runs == 2);  // the first candidate's two replicates, then nothing
  for (size_t c = 1; c < s.candidates.size(); ++c)
    CHECK(s.candidates[c].result.replicates_run == 0);
}
