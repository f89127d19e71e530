#include "calibrate/evaluation_journal.h"

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>

#include "core/io/scratch_dir.h"
#include "core/math/fnv1a.h"

using demcal::calibrate::EvaluationJournal;
using demcal::calibrate::ReplicateRecord;

namespace {

std::string FreshPath(const std::string& name) {
  // One folder per process: ctest runs test cases side by side.
  static const demcal::testing::ScratchDir dir("journal_test");
  const std::string path = dir.str(name);
  std::filesystem::remove(path);
  return path;
}

}  // namespace

TEST_CASE("journal records read back bit-identical after reopening", "[unit][calibrate]") {
  const std::string path = FreshPath("roundtrip.jsonl");
  const std::vector<double> params{0.1 + 0.2, 1.0 / 3.0};  // not representable in short decimals
  std::string error;
  {
    EvaluationJournal j;
    REQUIRE(j.Open(path, "study-A", &error));
    REQUIRE(j.Append({params, 0, 11, "ok", 33.123456789012345, 4.5}, &error));
    REQUIRE(j.Append({params, 1, 12, "not_settled", 0, 9.0}, &error));
  }
  EvaluationJournal j;
  REQUIRE(j.Open(path, "study-A", &error));
  CHECK(j.LoadedRecords() == 2);
  const ReplicateRecord* r = j.Find(params, 0, 11);
  REQUIRE(r != nullptr);
  CHECK(r->value == 33.123456789012345);
  CHECK(r->ok());
  const ReplicateRecord* failed = j.Find(params, 1, 12);
  REQUIRE(failed != nullptr);
  CHECK(failed->status == "not_settled");
  CHECK(j.Find(params, 1, 99) == nullptr);          // another seed is another run
  CHECK(j.Find({0.3, 1.0 / 3.0}, 0, 11) == nullptr);  // 0.3 != 0.1 + 0.2 in binary
}

TEST_CASE("journal drops a line cut off by a kill and appends cleanly after it", "[unit][calibrate]") {
  const std::string path = FreshPath("cut.jsonl");
  std::string error;
  {
    EvaluationJournal j;
    REQUIRE(j.Open(path, "s", &error));
    REQUIRE(j.Append({{0.5}, 0, 1, "ok", 30.0, 1.0}, &error));
  }
  { std::ofstream(path, std::ios::app) << R"({"parameters":[0.7],"replicate":0,"se)"; }
  {
    EvaluationJournal j;
    REQUIRE(j.Open(path, "s", &error));
    CHECK(j.LoadedRecords() == 1);
    REQUIRE(j.Append({{0.7}, 0, 1, "ok", 35.0, 1.0}, &error));
  }
  EvaluationJournal j;
  REQUIRE(j.Open(path, "s", &error));
  CHECK(j.LoadedRecords() == 2);
  REQUIRE(j.Find({0.7}, 0, 1) != nullptr);
  CHECK(j.Find({0.7}, 0, 1)->value == 35.0);
}

TEST_CASE("journal of another study or a foreign file is refused", "[unit][calibrate]") {
  const std::string path = FreshPath("other.jsonl");
  std::string error;
  {
    EvaluationJournal j;
    REQUIRE(j.Open(path, "study-A", &error));
  }
  EvaluationJournal other;
  CHECK_FALSE(other.Open(path, "study-B", &error));
  CHECK(error.find("different study") != std::string::npos);
  const std::string junk = FreshPath("junk.jsonl");
  { std::ofstream(junk) << "time,value\n1,2\n"; }
  EvaluationJournal j;
  CHECK_FALSE(j.Open(junk, "study-A", &error));
  CHECK(error.find(junk + ":1") != std::string::npos);
}

TEST_CASE("journal of an older format is refused with what to do", "[unit][calibrate]") {
  demcal::testing::ScratchDir dir("journal_format");
  const std::string path = dir.str("journal.jsonl");
  for (const char* format : {"demcal-journal/1", "demcal-journal/2"}) {
    std::ofstream(path, std::ios::trunc)
        << R"({"format": ")" << format << R"(", "study": "f"})" << "\n"
        << R"({"parameters": [0.5], "replicate": 0, "seed": 1, "status": "ok", "value": 3})" << "\n";
    EvaluationJournal j;
    std::string error;
    CHECK_FALSE(j.Open(path, "f", &error));
    CHECK(error == path + " was written by an older demcal (" + format +
                       "); move it away or use a new --out to start afresh");
  }
  std::ofstream(path, std::ios::trunc) << R"({"format": "demcal-journal/9", "study": "f"})" << "\n";
  EvaluationJournal newer;
  std::string error;
  CHECK_FALSE(newer.Open(path, "f", &error));
  CHECK_THAT(error, Catch::Contains("written by a newer demcal (demcal-journal/9)"));
}

// The study fingerprint in a journal header is core::Fnv1a64Hex of the study's description
// (workflow/calibration/study_runs.cc); the published FNV-1a 64 test vectors (Fowler, Noll, Vo,
// http://www.isthe.com/chongo/tech/comp/fnv/) pin the offset basis a truncated constant got wrong.
TEST_CASE("journal fingerprint is the FNV-1a 64 digest of the same bytes", "[unit][calibrate]") {
  using demcal::core::Fnv1a64Hex;
  using demcal::core::Fnv1a64Of;
  CHECK(Fnv1a64Hex("") == "cbf29ce484222325");  // the offset basis 14695981039346656037
  CHECK(Fnv1a64Hex("a") == "af63dc4c8601ec8c");
  CHECK(Fnv1a64Hex("foobar") == "85944171f73967e8");
  const std::string study = "{\"experiment\":\"aor\"}|seed=7|clumps=0";
  char expected[17];
  std::snprintf(expected, sizeof expected, "%016llx",
                static_cast<unsigned long long>(Fnv1a64Of(study)));
  CHECK(Fnv1a64Hex(study) == expected);
  demcal::core::Fnv1a64 streamed;
  streamed.Bytes(study.data(), study.size());
  CHECK(streamed.digest() == Fnv1a64Of(study));
}

TEST_CASE("journal records are validated line by line on loading", "[unit][calibrate]") {
  demcal::testing::ScratchDir dir("journal_validation");
  const std::string header = R"({"format": "demcal-journal/3", "study": "f"})";
  const std::string good = R"({"parameters": [0.5], "replicate": 0, "seed": 1, "status": "ok", "value": 30.0})";
  auto load = [&](const std::string& body) {
    std::ofstream(dir.str("j.jsonl"), std::ios::trunc) << header << "\n" << body << "\n";
    demcal::calibrate::EvaluationJournal j;
    std::string error;
    return j.Open(dir.str("j.jsonl"), "f", &error, 1) ? std::string("ok") : error;
  };
  CHECK(load(good) == "ok");
  CHECK(load(good + "\n" + good) == "ok");  // an identical duplicate is harmless
  CHECK_THAT(load(good + "\n" + R"({"parameters": [0.5], "replicate": 0, "seed": 1, "status": "ok", "value": 31.0})"),
             Catch::Contains("j.jsonl:3: a second record of the same run"));
  CHECK_THAT(load(R"({"parameters": "x", "replicate": 0, "seed": 1, "status": "ok", "value": 1})"),
             Catch::Contains("j.jsonl:2: parameters"));
  CHECK_THAT(load(R"({"parameters": [0.5], "replicate": 0, "seed": 1, "status": "ok"})"),
             Catch::Contains("exactly one of 'value' or 'values'"));
  CHECK_THAT(load(R"({"parameters": [0.5], "replicate": 0, "seed": "1", "status": "ok", "value": 1})"),
             Catch::Contains("seed"));
  CHECK_THAT(load(R"({"parameters": [0.5, 1], "replicate": 0, "seed": 1, "status": "ok", "value": 1})"),
             Catch::Contains("2 values, the study has 1"));
  CHECK_THAT(load(R"({"group": "g", "parameters": [0.5], "replicate": 0, "seed": 1, "status": "ok", "values": {"angle_deg": -1e5}})"),
             Catch::Contains("angle_deg") && Catch::Contains("outside [0, 90] deg"));
  CHECK_THAT(load(std::string(100000, '[')), Catch::Contains("j.jsonl:2: not a journal record"));
}

TEST_CASE("journal records carry host, rank and times; older records without them still load",
          "[unit][calibrate]") {
  demcal::testing::ScratchDir dir("journal_timing");
  const std::string path = dir.str("j.jsonl");
  std::string error;
  ReplicateRecord timed{{0.5}, 0, 1, "ok", 30.0, 2.5};
  timed.host = "node-7", timed.rank = 3;
  timed.start_unix_s = 1764806400.123456, timed.end_unix_s = 1764806402.623456;
  timed.batch_unix_s = 1764806400.0;
  {
    EvaluationJournal j;
    REQUIRE(j.Open(path, "f", &error, 1));
    REQUIRE(j.Append(timed, &error));
  }
  // A record written before the timing fields existed, then the same run again from a resumed
  // run on another host: the same run, not "other content".
  std::ofstream(path, std::ios::app)
      << R"({"parameters": [0.7], "replicate": 0, "seed": 1, "status": "ok", "value": 31.0})" << "\n"
      << R"({"parameters": [0.5], "replicate": 0, "seed": 1, "status": "ok", "value": 30.0, )"
      << R"("host": "other", "rank": 0, "start_unix_s": 5, "end_unix_s": 6, "batch_unix_s": 5})"
      << "\n";
  EvaluationJournal j;
  REQUIRE(j.Open(path, "f", &error, 1));
  CHECK(j.LoadedRecords() == 2);
  const ReplicateRecord* old = j.Find({0.7}, 0, 1);
  REQUIRE(old != nullptr);
  CHECK(old->host.empty());
  CHECK(old->start_unix_s == 0);
  const ReplicateRecord* r = j.Find({0.5}, 0, 1);
  REQUIRE(r != nullptr);
  CHECK(r->value == 30.0);

  auto load = [&](const std::string& extra) {
    std::ofstream(path, std::ios::trunc)
        << R"({"format": "demcal-journal/3", "study": "f"})" << "\n"
        << R"({"parameters": [0.5], "replicate": 0, "seed": 1, "status": "ok", "value": 30.0, )"
        << extra << "}\n";
    EvaluationJournal k;
    return k.Open(path, "f", &error, 1) ? std::string("ok") : error;
  };
  CHECK(load(R"("host": "a", "rank": 1, "start_unix_s": 10, "end_unix_s": 12)") == "ok");
  CHECK_THAT(load(R"("rank": -1)"), Catch::Contains("j.jsonl:2: rank"));
  CHECK_THAT(load(R"("host": 7)"), Catch::Contains("host"));
  CHECK_THAT(load(R"("start_unix_s": 10, "end_unix_s": 9)"),
             Catch::Contains("end_unix_s: must not be before start_unix_s"));
  CHECK_THAT(load(R"("start_unix_s": "now")"), Catch::Contains("start_unix_s"));
}

TEST_CASE("a read-only journal loads the file and appends in memory only", "[unit][calibrate]") {
  demcal::testing::ScratchDir dir("journal_read_only");
  const std::string path = dir.str("j.jsonl");
  std::string error;
  {
    EvaluationJournal writer;
    REQUIRE(writer.Open(path, "f", &error, 1));
    REQUIRE(writer.Append({{0.5}, 0, 1, "ok", 30.0, 1.0}, &error));
  }
  const auto size = std::filesystem::file_size(path);
  EvaluationJournal reader;
  REQUIRE(reader.Open(path, "f", &error, 1, /*read_only=*/true));
  CHECK(reader.Find({0.5}, 0, 1) != nullptr);
  REQUIRE(reader.Append({{0.6}, 0, 1, "ok", 31.0, 1.0}, &error));
  CHECK(reader.Find({0.6}, 0, 1) != nullptr);
  CHECK(std::filesystem::file_size(path) == size);
  EvaluationJournal missing;  // a worker may open it before the manager has written the header
  REQUIRE(missing.Open(dir.str("absent.jsonl"), "f", &error, 1, true));
  CHECK_FALSE(std::filesystem::exists(dir.str("absent.jsonl")));
}
