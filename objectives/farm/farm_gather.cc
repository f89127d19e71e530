// RunGathered (farm.h): tasks on threads of their own whose farm calls meet at a barrier. A
// round ends when every task still going has made its next call (or finished); the coordinating
// thread, the caller of RunGathered, then makes the round's calls in task order: each Rendezvous
// and Share as it is, and every RunBatch of the round as one batch (the tasks' runs one after
// another, task order). Every rank runs the same tasks to the same calls (SPMD), so every rank
// makes the same rounds, and only the coordinating thread, the one that joined the MPI job
// (MPI_THREAD_FUNNELED), talks to the other ranks.
#include "objectives/farm/farm_gather.h"

#include <algorithm>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

namespace demcal::objectives::farm {
namespace {

struct Call {
  enum Kind { kBatch, kRendezvous, kShare } kind = kBatch;
  const Job* job = nullptr;
  Options options;
  uint64_t fingerprint = 0;
  std::string* bytes = nullptr;
};

struct Gathering {
  std::mutex mutex;
  std::condition_variable cv;
  std::vector<std::optional<Call>> calls;  // per task: its call of this round
  std::vector<bool> finished;
  uint64_t round = 0;

  bool RoundReady() const {
    for (size_t k = 0; k < calls.size(); ++k)
      if (!finished[k] && !calls[k]) return false;
    return true;
  }
  bool AllFinished() const {
    return std::all_of(finished.begin(), finished.end(), [](bool f) { return f; });
  }
};

thread_local Gathering* t_gathering = nullptr;
thread_local size_t t_task = 0;

// Hands `call` to the coordinator and waits until it has been made.
bool Hand(const Call& call) {
  Gathering* g = t_gathering;
  if (!g) return false;
  std::unique_lock lock(g->mutex);
  const uint64_t round = g->round;
  g->calls[t_task] = call;
  g->cv.notify_all();
  g->cv.wait(lock, [&] { return g->round != round; });
  return true;
}

// The round's batches as one: task k's runs are tasks offset[k]..offset[k+1]−1.
void RunCombined(const std::vector<const Call*>& batches) {
  std::vector<int> offset{0};
  uint64_t fingerprint = 1469598103934665603ull;  // FNV-1a over (count, fingerprint) pairs
  for (const Call* c : batches) {
    offset.push_back(offset.back() + std::max(0, c->job->count));
    for (uint64_t v : {static_cast<uint64_t>(c->job->count), c->job->fingerprint})
      fingerprint = (fingerprint ^ v) * 1099511628211ull;
  }
  auto part = [&](int t) {
    const size_t k = std::upper_bound(offset.begin(), offset.end(), t) - offset.begin() - 1;
    return std::pair{batches[k]->job, t - offset[k]};
  };
  Job all;
  all.count = offset.back();
  all.fingerprint = fingerprint;
  all.run = [&](int t) {
    auto [job, u] = part(t);
    job->run(u);
  };
  all.save = [&](int t) {
    auto [job, u] = part(t);
    return job->save(u);
  };
  all.load = [&](int t, const std::string& b) {
    auto [job, u] = part(t);
    job->load(u, b);
  };
  all.done = [&](int t) {
    auto [job, u] = part(t);
    if (job->done) job->done(u);
  };
  all.started = [&](double unix_s) {
    for (const Call* c : batches)
      if (c->job->started) c->job->started(unix_s);
  };
  RunBatchHere(all, batches.front()->options);
}

}  // namespace

bool GatherBatch(const Job& job, const Options& options) {
  return Hand({.kind = Call::kBatch, .job = &job, .options = options});
}
bool GatherRendezvous(uint64_t fingerprint) {
  return Hand({.kind = Call::kRendezvous, .fingerprint = fingerprint});
}
bool GatherShare(std::string* bytes) { return Hand({.kind = Call::kShare, .bytes = bytes}); }

void RunGathered(const std::vector<std::function<void()>>& tasks) {
  if (t_gathering) {  // a task of a gathering: its own tasks one after another
    for (const auto& task : tasks) task();
    return;
  }
  Gathering g;
  g.calls.resize(tasks.size());
  g.finished.assign(tasks.size(), false);
  std::vector<std::exception_ptr> errors(tasks.size());
  std::vector<std::thread> threads;
  for (size_t k = 0; k < tasks.size(); ++k)
    threads.emplace_back([&, k] {
      t_gathering = &g, t_task = k;
      try {
        tasks[k]();
      } catch (...) {
        errors[k] = std::current_exception();
      }
      std::lock_guard lock(g.mutex);
      g.finished[k] = true;
      g.cv.notify_all();
    });
  for (;;) {
    std::vector<Call> round;
    {
      std::unique_lock lock(g.mutex);
      g.cv.wait(lock, [&] { return g.RoundReady(); });
      if (g.AllFinished()) break;
      for (auto& c : g.calls)
        if (c) round.push_back(*c);
    }
    std::vector<const Call*> batches;
    for (const Call& c : round) {
      if (c.kind == Call::kRendezvous) RendezvousHere(c.fingerprint);
      if (c.kind == Call::kShare) ShareHere(c.bytes);
      if (c.kind == Call::kBatch) batches.push_back(&c);
    }
    if (!batches.empty()) RunCombined(batches);
    std::lock_guard lock(g.mutex);
    for (auto& c : g.calls) c.reset();
    ++g.round;
    g.cv.notify_all();
  }
  for (std::thread& t : threads) t.join();
  for (const std::exception_ptr& e : errors)
    if (e) std::rethrow_exception(e);
}

}  // namespace demcal::objectives::farm
