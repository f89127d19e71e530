#include "workflow/reproduce/stage_journal.h"

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>

using namespace demcal::workflow;
namespace fs = std::filesystem;

namespace {
fs::path FreshDir(const std::string& name) {
  fs::path dir = fs::temp_directory_path() / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}
}  // namespace

TEST_CASE("stage journal: finished stages are read back after reopening", "[unit]") {
  fs::path dir = FreshDir("demcal_stage_journal_reopen");
  std::string path = (dir / "stages.jsonl").string(), error;
  {
    StageJournal j;
    REQUIRE(j.Open(path, "fp", &error));
    CHECK(j.Find("cohesion") == nullptr);
    REQUIRE(j.Record("cohesion", {{"coh", 1.6e-3}}, &error));
    REQUIRE(j.Record("segregation/uncoated/r0", {{"s_n", 1.2}}, &error));
    CHECK_FALSE(j.Record("cohesion", {}, &error));  // twice: refused
  }
  StageJournal j;
  REQUIRE(j.Open(path, "fp", &error));
  REQUIRE(j.Find("cohesion") != nullptr);
  CHECK((*j.Find("cohesion"))["coh"].get<double>() == Approx(1.6e-3));
  CHECK(j.Find("segregation/uncoated/r0") != nullptr);
  CHECK(j.size() == 2);
  fs::remove_all(dir);
}

TEST_CASE("stage journal: a line cut by a kill is dropped, then appending goes on", "[unit]") {
  fs::path dir = FreshDir("demcal_stage_journal_cut");
  std::string path = (dir / "stages.jsonl").string(), error;
  {
    StageJournal j;
    REQUIRE(j.Open(path, "fp", &error));
    REQUIRE(j.Record("a", 1, &error));
  }
  { std::ofstream(path, std::ios::app) << "{\"key\": \"b\", \"resu"; }  // kill -9 mid-write
  {
    StageJournal j;
    REQUIRE(j.Open(path, "fp", &error));
    CHECK(j.Find("b") == nullptr);
    REQUIRE(j.Record("b", 2, &error));
  }
  StageJournal j;
  REQUIRE(j.Open(path, "fp", &error));
  CHECK(j.Find("a") != nullptr);
  CHECK(j.Find("b") != nullptr);
  fs::remove_all(dir);
}

TEST_CASE("stage journal refuses another workflow's journal and edited lines", "[unit]") {
  fs::path dir = FreshDir("demcal_stage_journal_refuse");
  std::string path = (dir / "stages.jsonl").string(), error;
  {
    StageJournal j;
    REQUIRE(j.Open(path, "fp", &error));
  }
  StageJournal other;
  CHECK_FALSE(other.Open(path, "another", &error));
  CHECK(error.find("another workflow file or fidelity") != std::string::npos);
  { std::ofstream(path, std::ios::app) << "[1, 2]\n"; }
  StageJournal bad;
  CHECK_FALSE(bad.Open(path, "fp", &error));
  CHECK(error.find("stages.jsonl:2:") != std::string::npos);
  fs::remove_all(dir);
}
