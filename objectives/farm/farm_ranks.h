#pragma once
// The MPI side of the farm (farm.h), inside objectives/farm/ only: the one file that includes
// mpi.h implements these (farm_ranks.cc); in a build without MPI they are the one-rank answers.
#include "objectives/farm/farm.h"

namespace demcal::objectives::farm {

// farm.h's RunBatch when Size() > 1: the manager's queue or a worker's loop.
void RunBatchOverRanks(const Job& job, const Options& options);

}  // namespace demcal::objectives::farm
