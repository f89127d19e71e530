// The files demcal writes in place in --out (the lock, the calibration journal, the stage
// journal) are never written through a link planted at their name: the link is refused with a
// message naming it, and the file it points to keeps its bytes. AtomicFile replaces a link at
// its name with the new file (rename), leaving the target alone too.
#include <sys/stat.h>

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "calibrate/evaluation_journal.h"
#include "core/io/atomic_file.h"
#include "core/io/scratch_dir.h"
#include "outputs/output_lock.h"
#include "workflow/reproduce/stage_journal.h"

using demcal::testing::ScratchDir;

namespace {

constexpr const char* kLinkMessage =
    " is a symbolic link; demcal does not follow links for its lock/journal files";

std::string Contents(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

TEST_CASE("a lock file that is a link is refused and its target kept", "[unit][outputs]") {
  ScratchDir dir("lock_link");
  std::ofstream(dir.str("thesis.tex")) << "years of work\n";
  std::filesystem::create_directories(dir.str("out"));
  const std::string lock_path = dir.str("out/.demcal.lock");
  std::filesystem::create_symlink(dir.str("thesis.tex"), lock_path);
  demcal::workflow::OutputLock lock;
  std::string error;
  CHECK_FALSE(demcal::workflow::LockOutputDirectory(dir.str("out"), "demcal test", &lock, &error));
  CHECK_THAT(error, Catch::Contains(lock_path + kLinkMessage));
  CHECK(Contents(dir.str("thesis.tex")) == "years of work\n");

  // A dangling link: nothing may be created where it points, outside --out.
  std::filesystem::remove(lock_path);
  std::filesystem::create_symlink(dir.str("elsewhere"), lock_path);
  CHECK_FALSE(demcal::workflow::LockOutputDirectory(dir.str("out"), "demcal test", &lock, &error));
  CHECK_THAT(error, Catch::Contains(kLinkMessage));
  CHECK_FALSE(std::filesystem::exists(dir.str("elsewhere")));

  std::filesystem::remove(lock_path);  // a plain lock file works as before
  CHECK(demcal::workflow::LockOutputDirectory(dir.str("out"), "demcal test", &lock, &error));
  CHECK(lock.held());
}

TEST_CASE("journals that are links or FIFOs are refused at once", "[unit][outputs]") {
  ScratchDir dir("journal_link");
  std::ofstream(dir.str("notes.txt")) << "keep me\n";
  std::filesystem::create_symlink(dir.str("notes.txt"), dir.str("journal.jsonl"));
  std::filesystem::create_symlink(dir.str("notes.txt"), dir.str("stages.jsonl"));
  std::string error;
  {
    demcal::calibrate::EvaluationJournal journal;
    CHECK_FALSE(journal.Open(dir.str("journal.jsonl"), "study", &error));
    CHECK_THAT(error, Catch::Contains(dir.str("journal.jsonl") + kLinkMessage));
  }
  {
    demcal::workflow::StageJournal journal;
    CHECK_FALSE(journal.Open(dir.str("stages.jsonl"), "workflow", &error));
    CHECK_THAT(error, Catch::Contains(dir.str("stages.jsonl") + kLinkMessage));
  }
  CHECK(Contents(dir.str("notes.txt")) == "keep me\n");

  // A FIFO with no writer would block a plain read for ever.
  REQUIRE(::mkfifo(dir.str("pipe.jsonl").c_str(), 0600) == 0);
  {
    demcal::calibrate::EvaluationJournal journal;
    CHECK_FALSE(journal.Open(dir.str("pipe.jsonl"), "study", &error));
    CHECK_THAT(error, Catch::Contains("not a regular file but a FIFO"));
  }
  {
    demcal::workflow::StageJournal journal;
    CHECK_FALSE(journal.Open(dir.str("pipe.jsonl"), "workflow", &error));
    CHECK_THAT(error, Catch::Contains("not a regular file but a FIFO"));
  }
}

TEST_CASE("an atomically written file replaces a link instead of writing through it",
          "[unit][outputs]") {
  ScratchDir dir("atomic_link");
  std::ofstream(dir.str("users_file")) << "original\n";
  std::filesystem::create_symlink(dir.str("users_file"), dir.str("result.csv"));
  std::string error;
  REQUIRE(demcal::core::io::WriteFileAtomically(
      dir.str("result.csv"), [](std::ostream& out) { out << "a,b\n"; }, &error));
  CHECK_FALSE(std::filesystem::is_symlink(dir.str("result.csv")));
  CHECK(Contents(dir.str("result.csv")) == "a,b\n");
  CHECK(Contents(dir.str("users_file")) == "original\n");
}
