#pragma once
// Farm: a batch of independent runs (the replicates of a calibration batch) spread over what the
// job has: threads of this process, or the ranks of an MPI job (`mpirun -np N demcal ...`).
//
// The MPI farm is SPMD: every rank runs the same deterministic program (same files, optimiser,
// candidates) and reaches the same batches in the same order. At a batch the tasks are indices
// 0..count−1; rank 0, the manager, hands them out from a queue to free slots of the worker ranks
// (a free slot takes the next index, so long and short runs mix), each worker runs its task and
// sends back the result as bytes (Job::save), and at the end the manager sends every result to
// every worker (Job::load), so all ranks leave the batch with the same state. Only the manager
// writes files; the other ranks' stdout and stderr go to /dev/null (Session). Each batch starts
// with a check that every rank derived the same tasks (Job::fingerprint); a rank that differs
// aborts the job with a message rather than computing something else.
//
// Faults: a run still going after the run-time limit (Options::run_time_limit_s, or by default
// 4 × the median run time once 3 runs have finished) is copied to a free slot of another rank and
// the first result wins (runs are deterministic: both copies give the same values). Each
// simulation has its own wall-time budget, so no run, and no wait of the manager, is endless. A
// rank that dies ends the job (Open MPI aborts it); the evaluation journal then resumes the run.
//
// Without mpirun, or in a build without MPI (CMake option DEMCAL_MPI), Size() is 1 and RunBatch
// is objectives::RunReplicates: the threaded path, unchanged. No MPI header is included here.
//
//   objectives::farm::Session session(&argc, &argv);   // in main(), once
//   farm::RunBatch({.count = n, .fingerprint = f, .run = ..., .save = ..., .load = ...,
//                   .done = ...}, {.threads = 2});
//   return session.Finish(exit_code);  // every rank exits with the manager's code
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace demcal::objectives::farm {

// This process's rank and the job's rank count (0 of 1 without mpirun).
int Rank();
int Size();
inline bool IsManager() { return Rank() == 0; }
inline bool Farmed() { return Size() > 1; }

// The host name of this process ("" if it cannot be read) and the UTC time in seconds since the
// epoch, to the microsecond.
const std::string& HostName();
double UnixNow();

// Joins the MPI job when the process was started by mpirun (in an MPI build); otherwise nothing.
// On ranks other than 0, stdout and stderr then go to /dev/null (the farm's errors still show).
class Session {
 public:
  Session(int* argc, char*** argv);
  ~Session();
  Session(const Session&) = delete;
  Session& operator=(const Session&) = delete;
  // Ends the job: the manager tells every worker its exit code and waits for them; a worker
  // returns the manager's code. Call once, with what the command returned.
  int Finish(int exit_code);
};

struct Job {
  int count = 0;
  uint64_t fingerprint = 0;  // of the tasks (every rank must derive the same)
  std::function<void(int)> run;                       // runs task t here, into the caller's slot t
  std::function<std::string(int)> save;               // slot t's result as bytes (farmed only)
  std::function<void(int, const std::string&)> load;  // slot t's result from bytes (farmed only)
  std::function<void(int)> done;  // slot t holds its result (may be called from several threads)
  // Called on every rank before the runs, with the batch's start (UTC, s since the epoch): one
  // time for every job that RunGathered runs in one batch (the journals' batch_unix_s).
  std::function<void(double)> started;
};

struct Options {
  // Runs side by side: in this process (0: all cores), or per worker rank (0: 1, one rank per
  // core being mpirun's default layout).
  int threads = 0;
  // Farmed: copy a run to another rank after this (0: 4 × the median; infinity: never, for runs
  // that write a folder of their own, which a copy would write too).
  double run_time_limit_s = 0;
};

// Runs every task once and returns when each has its result on this rank. done(t) is called on
// every rank: on the manager as results arrive (the journal is written at once), elsewhere after
// the batch.
void RunBatch(const Job& job, const Options& options);

// Runs `tasks` side by side, one thread each, with the results of running them one after
// another: a task's farm calls (RunBatch, Rendezvous, Share) wait until every task still going
// has made its next one, and then the batches of that round run as one batch (the tasks' runs in
// task order), so calibrations that do not wait on each other fill the slots together. The
// tasks must make the same calls on every rank (as any farmed code does) and share nothing but
// what they hand to the farm. Returns when every task has; rethrows the first task's exception.
void RunGathered(const std::vector<std::function<void()>>& tasks);

// Farmed: the manager waits here until every rank has reached this point with the same
// fingerprint (e.g. after reading the journal, before the manager appends to it); workers go on.
void Rendezvous(uint64_t fingerprint);

// Farmed: the manager's `bytes` replace every worker's, and a worker waits here until they come,
// so a worker passes this point only after the manager has (e.g. after the manager has written a
// file every rank reads next, or decided something the workers must follow). A worker whose
// manager ended the job before this point exits with the manager's code. The manager goes on.
void Share(std::string* bytes);

}  // namespace demcal::objectives::farm
