// The farm without mpirun: one rank, the threaded path (each task run once, done once after it).
#include "objectives/farm/farm.h"

#include <atomic>
#include <catch2/catch.hpp>
#include <vector>

namespace farm = demcal::objectives::farm;

TEST_CASE("farm without mpirun runs every task once on threads, done after each", "[unit][farm]") {
  REQUIRE(farm::Size() == 1);
  REQUIRE(farm::IsManager());
  std::vector<std::atomic<int>> runs(20), dones(20);
  std::vector<int> slots(20, -1);
  farm::Job job;
  job.count = 20;
  job.run = [&](int t) {
    ++runs[t];
    slots[t] = t * t;
  };
  job.done = [&](int t) {
    CHECK(slots[t] == t * t);  // its own slot is filled before done
    ++dones[t];
  };
  farm::RunBatch(job, {.threads = 2});
  for (int t = 0; t < 20; ++t) {
    CHECK(runs[t] == 1);
    CHECK(dones[t] == 1);
  }
  farm::Rendezvous(42);  // one rank: returns at once
  CHECK(farm::UnixNow() > 1.7e9);  // after 2023-11: a clock in seconds since the epoch
}
