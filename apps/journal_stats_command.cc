#include "apps/journal_stats_command.h"

#include <iostream>
#include <memory>

#include "apps/cli_checks.h"
#include "outputs/exit_codes.h"
#include "workflow/journal_stats/journal_stats.h"

namespace demcal::apps {

Command AddJournalStatsCommand(CLI::App& parent) {
  struct Options {
    std::string dir;
    bool json = false;
  };
  auto o = std::make_shared<Options>();
  CLI::App* app = parent.add_subcommand(
      "journal-stats", "How the runs of a calibrate, reproduce or diagnose output folder used "
                       "the machines (from its evaluation journals)");
  app->add_option("dir", o->dir, "output folder (every demcal journal below it is read)")
      ->required()
      ->check(NonEmpty());
  app->add_flag("--json", o->json, "print JSON (demcal-journal-stats/1) instead of lines");
  return {app, [o] {
            workflow::JournalStats stats;
            std::string error;
            if (!workflow::ReadJournalStats(o->dir, &stats, &error)) {
              std::cerr << "error: " << error << "\n";
              return workflow::kExitInvalidInput;
            }
            if (o->json) std::cout << workflow::JournalStatsJson(stats).dump(2) << "\n";
            else std::cout << workflow::JournalStatsText(stats);
            return workflow::kExitOk;
          }};
}

}  // namespace demcal::apps
