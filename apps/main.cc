// demcal: the command-line front end. Each subcommand is one file exposing a CommandFactory
// (apps/command.h); register it with one line in kCommands below.
#include <CLI/CLI.hpp>
#include <exception>
#include <iostream>
#include <string>
#include <vector>

#include "apps/calibrate_command.h"
#include "apps/command.h"
#include "apps/experiment_command.h"
#include "apps/simulate_command.h"
#include "core/version.h"
#include "workflow/exit_codes.h"

namespace {

constexpr demcal::apps::CommandFactory kCommands[] = {
    &demcal::apps::AddSimulateCommand,
    &demcal::apps::AddExperimentCommand,
    &demcal::apps::AddCalibrateCommand,
};

}  // namespace

int main(int argc, char** argv) {
  using namespace demcal::apps;
  using namespace demcal::workflow;
  CLI::App app{"demcal: discrete element simulation and calibration of powders"};
  app.set_version_flag("--version,-V", std::string("demcal ") + demcal::kVersion);
  app.require_subcommand(1);
  app.footer("Run 'demcal <command> --help' for a command's options. Docs: docs/cli.md");
  std::vector<Command> commands;
  for (CommandFactory add : kCommands) commands.push_back(add(app));
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);  // prints help, version or the usage error
    return code == 0 ? kExitOk : kExitInvalidInput;
  }
  try {
    for (const Command& c : commands)
      if (c.app->parsed()) return c.run();
  } catch (const std::exception& e) {
    std::cerr << "internal error: " << e.what() << "\n";
    return kExitInternalError;
  }
  return kExitInvalidInput;
}
