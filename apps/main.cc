// demcal: the command-line front end. Each subcommand is one file exposing a CommandFactory
// (apps/command.h); register it with one line in kCommands below.
#include <CLI/CLI.hpp>
#include <exception>
#include <iostream>
#include <string>
#include <vector>

#include "apps/calibrate_command.h"
#include "apps/cohesion_command.h"
#include "apps/command.h"
#include "apps/diagnose_command.h"
#include "apps/experiment_command.h"
#include "apps/journal_stats_command.h"
#include "apps/export_command.h"
#include "apps/reproduce_command.h"
#include "apps/simulate_command.h"
#include "calibrate/solver_logging.h"
#include "core/version.h"
#include "objectives/farm/farm.h"
#include "outputs/exit_codes.h"

namespace {

constexpr demcal::apps::CommandFactory kCommands[] = {
    &demcal::apps::AddSimulateCommand,
    &demcal::apps::AddExperimentCommand,
    &demcal::apps::AddCalibrateCommand,
    &demcal::apps::AddReproduceCommand,
    &demcal::apps::AddCohesionCommand,
    &demcal::apps::AddDiagnoseCommand,
    &demcal::apps::AddJournalStatsCommand,
    &demcal::apps::AddExportCommand,
};

// The commands whose runs are farmed over the ranks of an MPI job (objectives/farm/farm.h); the
// others would have every rank write the same outputs.
bool Farmable(const std::string& name) {
  return name == "calibrate" || name == "diagnose" || name == "reproduce";
}

int RunCommandLine(int argc, char** argv) {
  using namespace demcal::apps;
  using namespace demcal::workflow;
  CLI::App app{"demcal: discrete element simulation and calibration of powders"};
  app.set_version_flag("--version,-V", std::string("demcal ") + demcal::kVersion);
  app.require_subcommand(1);
  app.footer("Run 'demcal <command> --help' for a command's options. Docs: docs/cli.md");
  std::vector<Command> commands;
  for (CommandFactory add : kCommands) commands.push_back(add(app));
  // CLI11 takes an unknown first word for a stray argument and answers "A subcommand is
  // required"; name the word and the commands instead.
  if (argc > 1 && argv[1][0] != '-') {
    const std::string word = argv[1];
    bool known = false;
    std::string names;
    for (const Command& c : commands) {
      known = known || c.app->get_name() == word;
      names += (names.empty() ? "" : ", ") + c.app->get_name();
    }
    if (!known) {
      std::cerr << "error: unknown command '" << word << "'; commands: " << names
                << " (demcal --help)\n";
      return kExitInvalidInput;
    }
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);  // prints help, version or the usage error
    return code == 0 ? kExitOk : kExitInvalidInput;
  }
  try {
    for (const Command& c : commands) {
      if (!c.app->parsed()) continue;
      if (demcal::objectives::farm::Farmed() && !Farmable(c.app->get_name())) {
        std::cerr << "error: demcal " << c.app->get_name() << " does not farm its runs over MPI "
                  << "ranks; run it without mpirun (--threads sets its cores)\n";
        return kExitInvalidInput;
      }
      const CLI::Option* quiet = c.app->get_option_no_throw("--quiet");
      demcal::calibrate::InitSolverLogging(argv[0], quiet && quiet->count() > 0);
      return c.run();
    }
  } catch (const std::bad_alloc&) {
    // Input validation bounds what a scene may ask for; running out anyway is the machine's
    // limit, not a bug.
    std::cerr << "error: out of memory; reduce the particle count or the outputs\n";
    return kExitRunFailed;
  } catch (const std::exception& e) {
    std::cerr << "internal error: " << e.what() << "\n";
    return kExitInternalError;
  }
  return kExitInvalidInput;
}

}  // namespace

int main(int argc, char** argv) {
  // Under mpirun every rank runs the same command; only rank 0 speaks (farm.h).
  demcal::objectives::farm::Session session(&argc, &argv);
  return session.Finish(RunCommandLine(argc, argv));
}
