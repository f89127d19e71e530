// The farm over MPI ranks (farm.h): the manager's queue, a worker's loop, the start and the end
// of the job. Messages go through farm_wire (the one place that talks MPI).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <map>
#include <mutex>
#include <thread>
#include <vector>

#include "objectives/farm/farm_gather.h"
#include "objectives/farm/farm_ranks.h"
#include "objectives/farm/farm_wire.h"

namespace demcal::objectives::farm {
namespace {

using wire::Message;
using wire::Reader;
using wire::Writer;

struct JobState {
  int rank = 0, size = 1;
  bool active = false, finished = false;
  uint64_t batch = 0, rendezvous = 0, share = 0;  // the last started, counted alike on every rank
};
JobState& State() {
  static JobState state;
  return state;
}

// What the manager knows of each worker rank.
struct Worker {
  uint64_t ready = 0;  // the batch it has entered (its slots are free from then on)
  uint64_t count = 0, fingerprint = 0;  // of its tasks in that batch
  int slots = 1, busy = 0;
};
struct Ledger {
  std::vector<Worker> workers;
  std::map<uint64_t, std::pair<uint64_t, uint64_t>> batches;  // batch -> count, fingerprint
  std::vector<double> durations_s;                             // of finished runs, any batch
};
Ledger& Books() {
  static Ledger ledger;
  return ledger;
}

std::string Text(const char* format, uint64_t a, uint64_t b = 0, uint64_t c = 0) {
  char buffer[256];
  std::snprintf(buffer, sizeof buffer, format, static_cast<unsigned long long>(a),
                static_cast<unsigned long long>(b), static_cast<unsigned long long>(c));
  return buffer;
}

// A worker's tasks in a batch must be the manager's (same count and fingerprint); checked when
// both are known (a READY can come before the manager has reached the batch).
void CheckReady(int rank) {
  const Worker& w = Books().workers[rank];
  const auto known = Books().batches.find(w.ready);
  if (known != Books().batches.end() && known->second != std::pair{w.count, w.fingerprint})
    wire::Abort(Text("rank %llu reached batch %llu with other tasks than rank 0 (%llu runs); "
                     "every rank must read the same files", rank, w.ready, w.count));
}

void TakeReady(const Message& m) {
  Reader in(m.bytes);
  Worker& w = Books().workers[m.source];
  w.ready = in.U64(), w.count = in.U64(), w.fingerprint = in.U64(), w.busy = 0;
  w.slots = static_cast<int>(std::clamp<uint64_t>(in.U64(), 1, 1 << 16));
  CheckReady(m.source);
}

// A message that has no place at this point of the program.
[[noreturn]] void Unexpected(const Message& m, const std::string& where) {
  static const char* const kNames[] = {"?",        "ready",      "task",  "result", "batch end",
                                       "stop",     "finished",   "rendezvous", "share"};
  const char* name = m.tag >= 1 && m.tag <= wire::kShare ? kNames[m.tag] : "?";
  wire::Abort(Text("rank %llu got '", State().rank) + name +
              Text("' from rank %llu ", m.source) + where +
              " (the ranks no longer run the same program; run without mpirun to see a "
              "rank's own error)");
}

double Seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

double Median(std::vector<double> v) {
  std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
  return v[v.size() / 2];
}

struct Copy {
  int task = 0, rank = 0;
  double start_s = 0;
};

void ManagerBatch(const Job& job, const Options& options) {
  Ledger& books = Books();
  const uint64_t batch = ++State().batch;
  books.batches[batch] = {static_cast<uint64_t>(job.count), job.fingerprint};
  for (size_t r = 1; r < books.workers.size(); ++r) CheckReady(static_cast<int>(r));
  std::vector<std::string> results(job.count);
  std::vector<int> copies(job.count, 0);
  std::vector<bool> have(job.count, false);
  std::vector<Copy> running;
  int next = 0, remaining = job.count;
  auto pause = std::chrono::microseconds(50);
  while (remaining > 0) {
    Message m;
    const bool got = wire::Poll(-1, &m);
    if (got) {
      pause = std::chrono::microseconds(50);
      if (m.tag == wire::kReady) {
        TakeReady(m);
      } else if (m.tag == wire::kResult) {
        Reader in(m.bytes);
        const uint64_t b = in.U64(), t = in.U64();
        if (b != batch) continue;  // a copy that lost in an earlier batch
        Worker& w = books.workers[m.source];
        w.busy = std::max(0, w.busy - 1);
        const auto copy = std::find_if(running.begin(), running.end(), [&](const Copy& c) {
          return c.task == static_cast<int>(t) && c.rank == m.source;
        });
        if (copy != running.end()) {
          books.durations_s.push_back(Seconds() - copy->start_s);
          running.erase(copy);
        }
        if (t >= have.size() || have[t]) continue;  // the other copy was first
        have[t] = true, --remaining;
        results[t] = in.Text();
        job.load(static_cast<int>(t), results[t]);
        if (job.done) job.done(static_cast<int>(t));
      } else {
        Unexpected(m, Text("in batch %llu", batch));  // e.g. a worker ended on an error
      }
    }
    // Hand the queue out to free slots, then copy overdue runs to free slots of other ranks.
    for (size_t r = 1; r < books.workers.size(); ++r)
      for (Worker& w = books.workers[r];
           w.ready == batch && w.busy < w.slots && next < job.count;) {
        wire::Send(static_cast<int>(r), wire::kTask, Writer().U64(batch).U64(next).Take());
        running.push_back({next++, static_cast<int>(r), Seconds()});
        ++w.busy;
      }
    const double limit_s = options.run_time_limit_s > 0 ? options.run_time_limit_s
                           : books.durations_s.size() >= 3
                               ? 4 * Median(books.durations_s)
                               : std::numeric_limits<double>::infinity();
    for (size_t k = 0; next == job.count && k < running.size(); ++k) {
      const Copy c = running[k];
      if (have[c.task] || copies[c.task] > 0 || Seconds() - c.start_s <= limit_s) continue;
      for (size_t r = 1; r < books.workers.size(); ++r) {
        Worker& w = books.workers[r];
        if (static_cast<int>(r) == c.rank || w.ready != batch || w.busy >= w.slots) continue;
        std::fprintf(stderr, "farm: run %d of batch %llu past %.1f s on rank %d; copied to rank "
                     "%zu (the first result is kept)\n", c.task,
                     static_cast<unsigned long long>(batch), limit_s, c.rank, r);
        wire::Send(static_cast<int>(r), wire::kTask, Writer().U64(batch).U64(c.task).Take());
        running.push_back({c.task, static_cast<int>(r), Seconds()});
        ++w.busy, ++copies[c.task];
        break;
      }
    }
    if (got) continue;
    wire::Flush();
    std::this_thread::sleep_for(pause);
    pause = std::min(pause * 2, std::chrono::microseconds(5000));
  }
  Writer all;
  all.U64(batch).U64(job.count);
  for (const std::string& r : results) all.Text(r);
  const std::string bytes = all.Take();
  for (int r = 1; r < State().size; ++r) wire::Send(r, wire::kBatchEnd, bytes);
}

// A worker's exit when the manager has ended the job: nothing more will come.
[[noreturn]] void StopHere(const Message& stop) {
  const int code = static_cast<int>(Reader(stop.bytes).U64());
  wire::Send(0, wire::kFinished, {});
  wire::Finalize();
  State().finished = true;
  std::fflush(stdout);
  std::_Exit(code);
}

void WorkerBatch(const Job& job, const Options& options) {
  const uint64_t batch = ++State().batch;
  const int slots = options.threads > 0 ? options.threads : 1;
  wire::Send(0, wire::kReady,
             Writer().U64(batch).U64(job.count).U64(job.fingerprint).U64(slots).Take());
  std::mutex mutex;
  std::vector<std::pair<int, std::string>> finished;
  std::vector<std::thread> threads;
  auto report = [&] {  // the results of finished runs go back to the manager
    std::lock_guard lock(mutex);
    for (auto& [t, bytes] : finished)
      wire::Send(0, wire::kResult, Writer().U64(batch).U64(t).Text(bytes).Take());
    finished.clear();
  };
  auto join = [&] {
    for (std::thread& t : threads) t.join();
    threads.clear();
    report();
  };
  auto pause = std::chrono::microseconds(50);
  for (;;) {
    report();
    Message m;
    if (!wire::Poll(0, &m)) {
      wire::Flush();
      std::this_thread::sleep_for(pause);
      pause = std::min(pause * 2, std::chrono::microseconds(5000));
      continue;
    }
    pause = std::chrono::microseconds(50);
    Reader in(m.bytes);
    if (m.tag == wire::kStop) {
      join();
      StopHere(m);
    }
    if (m.tag != wire::kTask && m.tag != wire::kBatchEnd) Unexpected(m, "while expecting a task");
    if (in.U64() != batch) Unexpected(m, Text("in batch %llu", batch));
    const uint64_t number = in.U64();  // the task, or the batch's task count
    if (m.tag == wire::kTask) {
      if (number >= static_cast<uint64_t>(job.count)) Unexpected(m, "(task out of range)");
      const int t = static_cast<int>(number);
      threads.emplace_back([&job, &mutex, &finished, t] {
        job.run(t);
        std::string bytes = job.save(t);
        std::lock_guard lock(mutex);
        finished.emplace_back(t, std::move(bytes));
      });
      continue;
    }
    if (number != static_cast<uint64_t>(job.count)) Unexpected(m, "(another task count)");
    join();  // a copy that lost still writes its slot: wait before the slots are loaded
    for (int k = 0; k < job.count; ++k) job.load(k, in.Text());
    if (job.done)
      for (int k = 0; k < job.count; ++k) job.done(k);
    return;
  }
}

}  // namespace

int Rank() { return State().rank; }
int Size() { return State().size; }

Session::Session(int* argc, char*** argv) {
  JobState& s = State();
  s.active = wire::Init(argc, argv, &s.rank, &s.size);
  if (s.active && s.rank == 0) Books().workers.assign(s.size, Worker{});
  if (s.active && s.rank != 0) wire::MuteOutput();  // they run the same program as rank 0
}

Session::~Session() {
  if (State().active && !State().finished) Finish(1);
}

int Session::Finish(int exit_code) {
  JobState& s = State();
  if (!s.active || s.finished) return exit_code;
  s.finished = true;
  if (s.rank == 0) {
    for (int r = 1; r < s.size; ++r) wire::Send(r, wire::kStop, Writer().U64(exit_code).Take());
    for (int stopped = 1; stopped < s.size;)  // late results and READYs are dropped here
      stopped += wire::Wait(-1).tag == wire::kFinished;
    wire::Finalize();
    return exit_code;
  }
  wire::Send(0, wire::kFinished, {});
  for (;;) {
    const Message m = wire::Wait(0);
    if (m.tag != wire::kStop) continue;
    wire::Finalize();
    return static_cast<int>(Reader(m.bytes).U64());
  }
}

void RunBatchOverRanks(const Job& job, const Options& options) {
  if (IsManager()) ManagerBatch(job, options);
  else WorkerBatch(job, options);
}

void Rendezvous(uint64_t fingerprint) {
  if (!GatherRendezvous(fingerprint)) RendezvousHere(fingerprint);
}

void Share(std::string* bytes) {
  if (!GatherShare(bytes)) ShareHere(bytes);
}

void RendezvousHere(uint64_t fingerprint) {
  if (!Farmed()) return;
  const uint64_t id = ++State().rendezvous;
  if (!IsManager()) {
    wire::Send(0, wire::kRendezvous, Writer().U64(id).U64(fingerprint).Take());
    return;
  }
  // A worker goes on after sending, so it may send the next rendezvous before the manager has
  // heard every rank at this one: those wait here for their turn.
  static std::multimap<uint64_t, std::pair<int, uint64_t>> early;  // id -> rank, fingerprint
  auto check = [&](int rank, uint64_t got) {
    if (got != fingerprint)
      wire::Abort(Text("rank %llu read other data than rank 0 (rendezvous %llu); every rank "
                       "must see the same files", rank, id));
  };
  int arrived = 1;
  for (auto [it, end] = early.equal_range(id); it != end; it = early.erase(it), ++arrived)
    check(it->second.first, it->second.second);
  while (arrived < Size()) {
    const Message m = wire::Wait(-1);
    if (m.tag == wire::kResult) continue;  // a copy that lost in the last batch
    if (m.tag == wire::kReady) {
      TakeReady(m);
      continue;
    }
    if (m.tag != wire::kRendezvous) Unexpected(m, "while waiting for every rank");
    Reader in(m.bytes);
    const uint64_t at = in.U64(), got = in.U64();
    if (at > id) {
      early.emplace(at, std::pair{m.source, got});
      continue;
    }
    if (at != id) wire::Abort(Text("rank %llu sent rendezvous %llu at %llu", m.source, at, id));
    check(m.source, got);
    ++arrived;
  }
}

void ShareHere(std::string* bytes) {
  if (!Farmed()) return;
  const uint64_t id = ++State().share;
  if (IsManager()) {
    const std::string message = Writer().U64(id).Text(*bytes).Take();
    for (int r = 1; r < Size(); ++r) wire::Send(r, wire::kShare, message);
    return;
  }
  const Message m = wire::Wait(0);
  if (m.tag == wire::kStop) StopHere(m);  // the manager ended the job before this point
  if (m.tag != wire::kShare) Unexpected(m, Text("while waiting for share %llu", id));
  Reader in(m.bytes);
  if (in.U64() != id) Unexpected(m, Text("(not share %llu)", id));
  *bytes = in.Text();
}

}  // namespace demcal::objectives::farm
