// ReadRegularFile (core/io/input_file.h) and OpenOwnFile (core/io/own_file.h): what is not a
// regular file is refused at once, saying what it is, and a link is refused where demcal writes
// in place, leaving the link's target as it was.
#include "core/io/input_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/io/own_file.h"
#include "core/io/scratch_dir.h"

using demcal::core::io::OpenOwnFile;
using demcal::core::io::ReadOptions;
using demcal::core::io::ReadRegularFile;
using demcal::testing::ScratchDir;

namespace {

std::string Contents(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string ReadError(const std::string& path, const ReadOptions& options = {}) {
  std::string text, error;
  return ReadRegularFile(path, "test file", 1 << 20, options, &text, &error) ? "ok" : error;
}

}  // namespace

TEST_CASE("ReadRegularFile says what a path that is not a regular file is", "[unit][io]") {
  ScratchDir dir("input_file");
  // A FIFO with no writer: a plain open would block for ever; this must return at once.
  REQUIRE(::mkfifo(dir.str("pipe").c_str(), 0600) == 0);
  CHECK_THAT(ReadError(dir.str("pipe")),
             Catch::Contains("cannot read the test file: not a regular file but a FIFO"));
  CHECK_THAT(ReadError(dir.str()), Catch::Contains("it is a directory, not a file"));
  CHECK_THAT(ReadError("/dev/zero"), Catch::Contains("not a regular file but a character device"));
  CHECK_THAT(ReadError(dir.str("missing")), Catch::Contains("No such file or directory"));
  std::string text = "stale";
  std::string error;
  CHECK(ReadRegularFile(dir.str("missing"), "journal", 1 << 20, {.missing_is_empty = true}, &text,
                        &error));
  CHECK(text.empty());
  std::ofstream(dir.str("big")) << std::string(2048, 'x');
  std::string small;
  CHECK_FALSE(ReadRegularFile(dir.str("big"), "test file", 1024, {}, &small, &error));
  CHECK_THAT(error, Catch::Contains("2048 bytes"));
}

TEST_CASE("ReadRegularFile follows a link for inputs and refuses one for own files", "[unit][io]") {
  ScratchDir dir("input_file_link");
  std::ofstream(dir.str("target")) << "user data\n";
  std::filesystem::create_symlink(dir.str("target"), dir.str("link"));
  CHECK(ReadError(dir.str("link")) == "ok");  // a user's input may be a link
  CHECK(ReadError(dir.str("link"), {.refuse_link = true}) ==
        dir.str("link") +
            " is a symbolic link; demcal does not follow links for its lock/journal files");
}

TEST_CASE("OpenOwnFile refuses a link, dangling or not, and leaves its target alone",
          "[unit][io]") {
  ScratchDir dir("own_file");
  std::ofstream(dir.str("users_file")) << "precious\n";
  std::filesystem::create_symlink(dir.str("users_file"), dir.str("own"));
  std::string error;
  CHECK(OpenOwnFile(dir.str("own"), O_RDWR | O_CREAT, &error) == -1);
  CHECK_THAT(error, Catch::Contains("own is a symbolic link; demcal does not follow links"));
  CHECK(Contents(dir.str("users_file")) == "precious\n");

  std::filesystem::create_symlink(dir.str("nowhere"), dir.str("dangling"));
  CHECK(OpenOwnFile(dir.str("dangling"), O_WRONLY | O_CREAT | O_APPEND, &error) == -1);
  CHECK_THAT(error, Catch::Contains("is a symbolic link"));
  CHECK_FALSE(std::filesystem::exists(dir.str("nowhere")));  // nothing created at the target

  REQUIRE(::mkfifo(dir.str("pipe").c_str(), 0600) == 0);
  CHECK(OpenOwnFile(dir.str("pipe"), O_RDWR | O_CREAT, &error) == -1);
  CHECK_THAT(error, Catch::Contains("not a regular file"));

  const int fd = OpenOwnFile(dir.str("fresh"), O_WRONLY | O_CREAT | O_APPEND, &error);
  CHECK(fd >= 0);
  if (fd >= 0) ::close(fd);
  CHECK(std::filesystem::is_regular_file(dir.str("fresh")));
}
