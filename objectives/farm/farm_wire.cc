#include "objectives/farm/farm_wire.h"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <list>
#include <thread>

#ifdef DEMCAL_HAVE_MPI
#include <mpi.h>
#endif

namespace demcal::objectives::farm::wire {

uint64_t Reader::U64() {
  uint64_t v = 0;
  if (at_ + sizeof v > bytes_.size()) Abort("a message ended early (a protocol error)");
  std::memcpy(&v, bytes_.data() + at_, sizeof v);
  at_ += sizeof v;
  return v;
}

std::string Reader::Text() {
  const uint64_t n = U64();
  if (n > bytes_.size() - at_) Abort("a message ended early (a protocol error)");
  std::string s = bytes_.substr(at_, n);
  at_ += n;
  return s;
}

namespace {

int& MessageFd() {
  static int fd = 2;  // stderr, or its copy once the rank is muted
  return fd;
}

void PrintError(const std::string& message) {
  ::dprintf(MessageFd(), "error: MPI farm: %s\n", message.c_str());
}

}  // namespace

void MuteOutput() {
  const int null = ::open("/dev/null", O_WRONLY | O_CLOEXEC);
  const int kept = ::dup(2);
  if (null < 0 || kept < 0) return;
  std::fflush(stdout);
  std::fflush(stderr);
  MessageFd() = kept;
  ::dup2(null, 1);
  ::dup2(null, 2);
  ::close(null);
}

Message Wait(int from) {
  Message m;
  // 50 µs growing to 5 ms: a reply is picked up quickly, an idle wait costs next to no CPU.
  std::chrono::microseconds pause(50);
  while (!Poll(from, &m)) {
    Flush();
    std::this_thread::sleep_for(pause);
    pause = std::min(pause * 2, std::chrono::microseconds(5000));
  }
  return m;
}

#ifdef DEMCAL_HAVE_MPI

namespace {

struct Outgoing {
  std::string bytes;
  MPI_Request request = MPI_REQUEST_NULL;
};
std::list<Outgoing>& Outbox() {
  static std::list<Outgoing> outbox;  // list: the bytes stay where MPI was told they are
  return outbox;
}

}  // namespace

bool Init(int* argc, char*** argv, int* rank, int* size) {
  // Only a process started by a launcher joins a job: a plain `demcal` never pays for MPI's
  // start-up (and works where no launcher is installed).
  const bool launched = std::getenv("OMPI_COMM_WORLD_SIZE") || std::getenv("PMI_SIZE") ||
                        std::getenv("PMIX_RANK");
  if (!launched) return false;
  int provided = 0;
  // Only the main thread calls MPI; runs go on other threads meanwhile.
  if (MPI_Init_thread(argc, argv, MPI_THREAD_FUNNELED, &provided) != MPI_SUCCESS) return false;
  MPI_Comm_rank(MPI_COMM_WORLD, rank);
  MPI_Comm_size(MPI_COMM_WORLD, size);
  return true;
}

void Finalize() {
  Drain();
  MPI_Finalize();
}

void Send(int to, Tag tag, std::string bytes) {
  Outgoing& out = Outbox().emplace_back();
  out.bytes = std::move(bytes);
  MPI_Isend(out.bytes.data(), static_cast<int>(out.bytes.size()), MPI_BYTE, to, tag,
            MPI_COMM_WORLD, &out.request);
  Flush();
}

void Flush() {
  std::list<Outgoing>& outbox = Outbox();
  for (auto it = outbox.begin(); it != outbox.end();) {
    int done = 0;
    MPI_Test(&it->request, &done, MPI_STATUS_IGNORE);
    it = done ? outbox.erase(it) : std::next(it);
  }
}

void Drain() {
  for (Outgoing& out : Outbox()) MPI_Wait(&out.request, MPI_STATUS_IGNORE);
  Outbox().clear();
}

bool Poll(int from, Message* message) {
  int flag = 0;
  MPI_Status status;
  MPI_Iprobe(from < 0 ? MPI_ANY_SOURCE : from, MPI_ANY_TAG, MPI_COMM_WORLD, &flag, &status);
  if (!flag) return false;
  int count = 0;
  MPI_Get_count(&status, MPI_BYTE, &count);
  message->source = status.MPI_SOURCE;
  message->tag = status.MPI_TAG;
  message->bytes.assign(static_cast<size_t>(count), '\0');
  MPI_Recv(message->bytes.data(), count, MPI_BYTE, status.MPI_SOURCE, status.MPI_TAG,
           MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  return true;
}

void Abort(const std::string& message) {
  PrintError(message);
  MPI_Abort(MPI_COMM_WORLD, 1);
  std::abort();
}

#else  // a build without MPI: one rank, nothing to send

bool Init(int*, char***, int*, int*) { return false; }
void Finalize() {}
void Send(int, Tag, std::string) {}
void Flush() {}
void Drain() {}
bool Poll(int, Message*) { return false; }
void Abort(const std::string& message) {
  PrintError(message);
  std::abort();
}

#endif

}  // namespace demcal::objectives::farm::wire
