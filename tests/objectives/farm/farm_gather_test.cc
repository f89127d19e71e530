// RunGathered without mpirun: tasks on threads whose batches go out together, one farm batch a
// round, with each task's results those of running it alone.
#include <atomic>
#include <catch2/catch.hpp>
#include <map>
#include <mutex>
#include <stdexcept>
#include <vector>

#include "objectives/farm/farm.h"

namespace farm = demcal::objectives::farm;

namespace {

// A task that runs `batches` batches; batch b has 1 + (seed + b + last sum) % 4 runs, so its
// calls depend on its own earlier results (as an optimiser's do). Run t of a batch gives
// seed·1000 + 10·b + t. Records every batch start it was handed.
struct Chain {
  int seed = 0, batches = 0;
  std::vector<int> sums;
  std::vector<double> starts;
  void Run() {
    int last = 0;
    for (int b = 0; b < batches; ++b) {
      std::vector<int> slots(1 + (seed + b + last) % 4, -1);
      farm::Job job;
      job.count = static_cast<int>(slots.size());
      job.run = [&](int t) { slots[t] = seed * 1000 + 10 * b + t; };
      job.started = [&](double s) { starts.push_back(s); };
      if (b == 1) farm::Rendezvous(7);  // other farm calls meet at the barrier too
      farm::RunBatch(job, {.threads = 2});
      last = 0;
      for (int v : slots) last += v;
      sums.push_back(last);
    }
  }
};

}  // namespace

TEST_CASE("farm: tasks run together give the results of running them one after another",
          "[unit][farm]") {
  std::vector<Chain> alone{{1, 3}, {2, 5}, {3, 1}}, together = alone;
  for (Chain& c : alone) c.Run();
  std::vector<std::function<void()>> tasks;
  for (Chain& c : together) tasks.push_back([&c] { c.Run(); });
  farm::RunGathered(tasks);
  for (size_t k = 0; k < alone.size(); ++k) {
    CHECK(together[k].sums == alone[k].sums);
    REQUIRE(together[k].starts.size() == together[k].sums.size());
  }
  // Round r's batches went out as one: the same start for every task still going.
  for (int r = 0; r < 5; ++r) {
    std::vector<double> at;
    for (const Chain& c : together)
      if (r < c.batches) at.push_back(c.starts[r]);
    for (double s : at) CHECK(s == at.front());
    if (r > 0) CHECK(together[1].starts[r] >= together[1].starts[r - 1]);
  }
}

TEST_CASE("farm: a task's exception reaches the caller of RunGathered after the others end",
          "[unit][farm]") {
  Chain other{4, 3};
  std::vector<std::function<void()>> tasks{[] { throw std::runtime_error("bad input"); },
                                           [&] { other.Run(); }};
  CHECK_THROWS_WITH(farm::RunGathered(tasks), "bad input");
  CHECK(other.sums.size() == 3);  // not left waiting at the barrier
}
