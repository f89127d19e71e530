#pragma once
// Command: one `demcal` subcommand. Each subcommand lives in its own file and exposes a factory
// that adds itself (name, help, options) to the parent CLI11 app and returns the action to run
// when it was selected. main.cc lists the factories; adding a subcommand (experiment,
// calibrate, ...) is one new file plus one line in that list.
//
// The action returns a process exit code (outputs/exit_codes.h); options parsed by CLI11 live in
// state owned by the action (captured shared_ptr), so they outlive the parse.
#include <CLI/CLI.hpp>
#include <functional>

namespace demcal::apps {

struct Command {
  CLI::App* app = nullptr;   // the subcommand, owned by the parent app
  std::function<int()> run;  // runs the command after a successful parse
};

using CommandFactory = Command (*)(CLI::App& parent);

}  // namespace demcal::apps
