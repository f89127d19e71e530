#pragma once
// `demcal journal-stats DIR [--json]`: simulations, run times, busy fraction per (host, rank) and
// the critical path of the evaluation journals under DIR (workflow/journal_stats).
#include "apps/command.h"

namespace demcal::apps {

Command AddJournalStatsCommand(CLI::App& parent);

}  // namespace demcal::apps
