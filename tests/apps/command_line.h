#pragma once
// Test helpers for the command tests. RunCli runs one `demcal` subcommand in this process the
// way apps/main.cc does (parse; a CLI11 error or --help is printed by CLI::App::exit, help exits
// 0 and any other parse error 2; else the command's action), capturing what it prints; the
// Check* functions state the three outcomes the tests look for (help shown, arguments refused,
// input refused). The real binary's exit codes and messages are checked end to end by
// tests/bad_inputs/ (the cli_* cases).
#include <CLI/CLI.hpp>
#include <algorithm>
#include <catch2/catch.hpp>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "apps/command.h"
#include "outputs/exit_codes.h"

namespace demcal::testing {

struct CliOutcome {
  int exit_code = -1;
  bool ran = false;  // the command's action ran (the arguments parsed)
  std::string out;   // stdout: help, and what the action printed there
  std::string err;   // stderr: the parse error, or the action's messages
  std::string text() const { return out + err; }
};

// Sends a standard stream into a string while it lives.
class CapturedStream {
 public:
  explicit CapturedStream(std::ostream& stream)
      : stream_(stream), old_(stream.rdbuf(buffer_.rdbuf())) {}
  ~CapturedStream() { stream_.rdbuf(old_); }
  CapturedStream(const CapturedStream&) = delete;
  CapturedStream& operator=(const CapturedStream&) = delete;
  std::string str() const { return buffer_.str(); }

 private:
  std::ostream& stream_;
  std::ostringstream buffer_;
  std::streambuf* old_;
};

// `demcal ARGS...` with only the command that `add` registers; args[0] is the command's name.
inline CliOutcome RunCli(apps::CommandFactory add, std::vector<std::string> args) {
  CLI::App app{"demcal"};
  app.require_subcommand(1);
  const apps::Command command = add(app);
  std::reverse(args.begin(), args.end());  // CLI11 takes the words last first
  CliOutcome outcome;
  CapturedStream out(std::cout), err(std::cerr);
  try {
    app.parse(args);
    outcome.ran = true;
    outcome.exit_code = command.run();
  } catch (const CLI::ParseError& e) {
    std::ostringstream help, error;
    outcome.exit_code =
        app.exit(e, help, error) == 0 ? workflow::kExitOk : workflow::kExitInvalidInput;
    std::cout << help.str();
    std::cerr << error.str();
  }
  outcome.out = out.str();
  outcome.err = err.str();
  return outcome;
}

// `demcal NAME --help` exits 0 without running the command and shows every one of `words`.
inline void CheckHelpShows(apps::CommandFactory add, const std::string& name,
                           const std::vector<std::string>& words) {
  const CliOutcome help = RunCli(add, {name, "--help"});
  CHECK(help.exit_code == workflow::kExitOk);
  CHECK_FALSE(help.ran);
  for (const std::string& word : words) CHECK_THAT(help.out, Catch::Contains(word));
}

// `demcal ARGS...` is refused before the command runs, with exit code 2 and a message that
// contains `named` (the option, or what is missing).
inline void CheckRefused(apps::CommandFactory add, const std::vector<std::string>& args,
                         const std::string& named) {
  std::string line = "demcal";
  for (const std::string& arg : args) line += " " + arg;
  INFO(line);
  const CliOutcome refused = RunCli(add, args);
  CHECK(refused.exit_code == workflow::kExitInvalidInput);
  CHECK_FALSE(refused.ran);
  CHECK_THAT(refused.err, Catch::Contains(named));
}

// `demcal ARGS...` parses, then the command refuses its input (a file, a name, a held --out):
// exit code 2 and a message that contains `named`.
inline void CheckInputRefused(apps::CommandFactory add, const std::vector<std::string>& args,
                              const std::string& named) {
  std::string line = "demcal";
  for (const std::string& arg : args) line += " " + arg;
  INFO(line);
  const CliOutcome refused = RunCli(add, args);
  CHECK(refused.ran);
  CHECK(refused.exit_code == workflow::kExitInvalidInput);
  CHECK_THAT(refused.err, Catch::Contains(named));
}

}  // namespace demcal::testing
