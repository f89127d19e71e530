#include "apps/journal_stats_command.h"

#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "apps/cli_checks.h"
#include "outputs/exit_codes.h"
#include "workflow/journal_stats/journal_stats.h"
#include "workflow/journal_stats/wall_time_model.h"

namespace demcal::apps {

Command AddJournalStatsCommand(CLI::App& parent) {
  struct Options {
    std::string dir;
    bool json = false;
    std::vector<int> model_ranks;
  };
  auto o = std::make_shared<Options>();
  CLI::App* app = parent.add_subcommand(
      "journal-stats", "How the runs of a calibrate, reproduce or diagnose output folder used "
                       "the machines (from its evaluation journals)");
  app->add_option("dir", o->dir, "output folder (every demcal journal below it is read)")
      ->required()
      ->check(NonEmpty());
  app->add_flag("--json", o->json, "print JSON (demcal-journal-stats/1) instead of lines");
  app->add_option("--model-ranks", o->model_ranks,
                  "also predict the wall span at these rank counts from the measured run times "
                  "(e.g. 8,64,512; docs/scale.md)")
      ->delimiter(',')
      ->check(CLI::Range(1, 1 << 20));
  return {app, [o] {
            workflow::JournalStats stats;
            std::string error;
            if (!workflow::ReadJournalStats(o->dir, &stats, &error)) {
              std::cerr << "error: " << error << "\n";
              return workflow::kExitInvalidInput;
            }
            nlohmann::ordered_json json = workflow::JournalStatsJson(stats);
            std::string text = workflow::JournalStatsText(stats);
            if (!o->model_ranks.empty()) {
              std::vector<workflow::JournalRun> runs;
              int journals = 0;
              if (!workflow::ReadJournalRuns(o->dir, &runs, &journals, &error)) {
                std::cerr << "error: " << error << "\n";
                return workflow::kExitInvalidInput;
              }
              const workflow::WallTimeModel model = workflow::ModelWallTime(runs, o->model_ranks);
              json["wall_time_model"] = workflow::WallTimeModelJson(model);
              text += workflow::WallTimeModelText(model);
            }
            if (o->json) std::cout << json.dump(2) << "\n";
            else std::cout << text;
            return workflow::kExitOk;
          }};
}

}  // namespace demcal::apps
