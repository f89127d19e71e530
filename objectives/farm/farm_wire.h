#pragma once
// The farm's messages (farm.h) as bytes, and their transport between ranks. Only the farm's own
// files include this; mpi.h stays inside farm_wire.cc.
//
// Payloads are written in this machine's byte order: every rank of a job runs the same binary
// on the same architecture (a heterogeneous job is not supported).
#include <cstdint>
#include <string>
#include <utility>

namespace demcal::objectives::farm::wire {

enum Tag : int {
  kReady = 1,   // worker → manager: batch, count, fingerprint, slots
  kTask,        // manager → worker: batch, task
  kResult,      // worker → manager: batch, task, bytes
  kBatchEnd,    // manager → worker: batch, every result
  kStop,        // manager → worker: the exit code; the job is over
  kFinished,    // worker → manager: the worker has stopped
  kRendezvous,  // worker → manager: rendezvous number, fingerprint
  kShare,       // manager → worker: share number, the manager's bytes
};

class Writer {
 public:
  Writer& U64(uint64_t v) {
    bytes_.append(reinterpret_cast<const char*>(&v), sizeof v);
    return *this;
  }
  Writer& Text(const std::string& s) {
    U64(s.size());
    bytes_ += s;
    return *this;
  }
  std::string&& Take() { return std::move(bytes_); }

 private:
  std::string bytes_;
};

// Reads what a Writer wrote; a short or malformed message aborts the job (a protocol bug).
class Reader {
 public:
  explicit Reader(const std::string& bytes) : bytes_(bytes) {}
  uint64_t U64();
  std::string Text();

 private:
  const std::string& bytes_;
  size_t at_ = 0;
};

struct Message {
  int source = -1;
  int tag = 0;
  std::string bytes;
};

// MPI's world (Init joins the job when started by mpirun and the build has MPI).
bool Init(int* argc, char*** argv, int* rank, int* size);
void Finalize();

// Sends without blocking (the bytes are kept until delivered); Flush completes what it can, and
// Drain waits for everything sent.
void Send(int to, Tag tag, std::string bytes);
void Flush();
void Drain();

// The next message from `from` (−1: any rank), if one has arrived.
bool Poll(int from, Message* message);
// Waits for the next message, sleeping between polls (a waiting rank leaves its core to runs).
Message Wait(int from);

// Sends this process's stdout and stderr (std::cout, printf, the optimisers' logs) to /dev/null,
// for the ranks other than 0, which run the same program; Abort still reaches the terminal.
void MuteOutput();

// Prints "error: MPI farm: <message>" and ends the whole job with exit code 1.
[[noreturn]] void Abort(const std::string& message);

}  // namespace demcal::objectives::farm::wire
