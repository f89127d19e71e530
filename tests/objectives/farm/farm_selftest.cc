// farm_selftest: the MPI farm (objectives/farm/farm.h) on tasks with known results and times, run
// under `mpirun -np 3` by tests/objectives/farm/CMakeLists.txt.
//   farm_selftest copy DIR: task 0 sleeps 4 s the first time it runs anywhere (a marker file in
//     DIR named after the job, removed at the end), then 0.05 s; with a 0.5 s run-time limit
//     the manager copies it to the other worker and ends the batch long before 4 s. Every rank
//     must end both batches with every task's result; exit 0 when so.
//   farm_selftest diverge: rank 2 derives other tasks; the job must abort with a message.
#include <fcntl.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <thread>
#include <vector>

#include "objectives/farm/farm.h"

namespace farm = demcal::objectives::farm;

namespace {

// The job's marker for task 0 (PMIX_NAMESPACE: the same on every rank of one job).
std::string Marker(const std::string& dir, int salt) {
  const char* job = std::getenv("PMIX_NAMESPACE");
  return dir + "/farm_selftest_task0_" + (job ? job : "job") + "_" + std::to_string(salt);
}

// Runs one batch of `count` tasks whose result is t·t + salt; false if a slot is wrong.
bool Batch(int count, int salt, const std::string& marker_dir, bool diverge, double* wall_s) {
  std::vector<std::string> slots(count);
  farm::Job job;
  job.count = count;
  job.fingerprint = 1000 * count + salt + (diverge && farm::Rank() == 2);
  job.run = [&](int t) {
    bool first = false;
    if (t == 0 && !marker_dir.empty()) {
      const int fd = ::open(Marker(marker_dir, salt).c_str(), O_CREAT | O_EXCL | O_WRONLY, 0600);
      first = fd >= 0;
      if (fd >= 0) ::close(fd);
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(first ? 4000 : 50));
    slots[t] = std::to_string(t * t + salt);
  };
  job.save = [&](int t) { return slots[t]; };
  job.load = [&](int t, const std::string& bytes) { slots[t] = bytes; };
  const auto start = std::chrono::steady_clock::now();
  farm::RunBatch(job, {.threads = 1, .run_time_limit_s = 0.5});
  *wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  for (int t = 0; t < count; ++t)
    if (slots[t] != std::to_string(t * t + salt)) return false;
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  farm::Session session(&argc, &argv);
  const std::string mode = argc > 1 ? argv[1] : "";
  const std::string dir = mode == "copy" && argc > 2 ? argv[2] : "";
  if (farm::Size() != 3) {
    std::fprintf(stderr, "farm_selftest: run under mpirun -np 3 (got %d ranks)\n", farm::Size());
    return session.Finish(2);
  }
  double first_s = 0, second_s = 0;
  const bool diverge = mode == "diverge";
  bool ok = Batch(6, 1, dir, diverge, &first_s);
  ok = Batch(4, 2, "", diverge, &second_s) && ok;
  // The manager must not have waited for the slow copy.
  const bool in_time = !farm::IsManager() || first_s < 3;
  if (farm::IsManager())
    std::printf("farm_selftest: batch 1 (a 4 s run copied after 0.5 s): %.2f s, batch 2: %.2f s, "
                "results %s: %s\n", first_s, second_s, ok ? "right" : "WRONG",
                ok && in_time ? "pass" : "FAIL");
  std::fflush(stdout);
  if (farm::IsManager() && !dir.empty()) ::unlink(Marker(dir, 1).c_str());
  return session.Finish(ok && in_time ? 0 : 1);
}
