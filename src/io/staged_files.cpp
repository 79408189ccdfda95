#include "tracked_vehicle_dynamics/io/staged_files.h"

#include <pthread.h>
#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>

namespace tracked_vehicle_dynamics {
namespace io {

namespace {

// Fixed slots, no allocation: the handler may only read them and call unlink (async-signal-safe).
// A slot is free (0), being written or cleared (1), holds a staged path (2), or holds one that
// untrackStagedFile() is comparing (3: still staged, its path unchanged, so the handler removes
// it; review 167: a slot hidden while another writer's was looked up kept its file). The
// handler reads a path only in states 2 and 3, set after the path is complete.
constexpr int kSlots = 64;
constexpr std::size_t kMaxPath = 4096;
struct Slot {
  std::atomic<int> state{0};
  char path[kMaxPath];
};
Slot slots[kSlots];

enum : int { kFree = 0, kBusy = 1, kStaged = 2, kComparing = 3 };

extern "C" void removeAndDie(int signal_number) {
  const int saved = errno;
  for (Slot& slot : slots) {
    const int state = slot.state.load(std::memory_order_acquire);
    if (state == kStaged || state == kComparing)
      ::unlink(slot.path);
  }
  errno = saved;
  // The default action: the process ends by the signal, as it would have without the handler.
  struct sigaction action = {};
  action.sa_handler = SIG_DFL;
  sigemptyset(&action.sa_mask);
  ::sigaction(signal_number, &action, nullptr);
  ::raise(signal_number);
}

}  // namespace

SignalsHeld::SignalsHeld() {
  sigset_t stopping;
  sigemptyset(&stopping);
  for (const int signal_number : {SIGINT, SIGTERM, SIGHUP})
    sigaddset(&stopping, signal_number);
  ::pthread_sigmask(SIG_BLOCK, &stopping, &saved_);
}

SignalsHeld::~SignalsHeld() {
  ::pthread_sigmask(SIG_SETMASK, &saved_, nullptr);
}

void trackStagedFile(const std::string& path) {
  if (path.size() >= kMaxPath)
    return;
  for (Slot& slot : slots) {
    int expected = kFree;
    if (slot.state.compare_exchange_strong(expected, kBusy, std::memory_order_acquire)) {
      std::memcpy(slot.path, path.c_str(), path.size() + 1);
      slot.state.store(kStaged, std::memory_order_release);
      return;
    }
  }
}

void untrackStagedFile(const std::string& path) {
  for (Slot& slot : slots) {
    int expected = kStaged;
    // Claimed before it is compared (another thread's untrack of the same slot cannot race it),
    // and still removed by the handler meanwhile.
    if (!slot.state.compare_exchange_strong(expected, kComparing, std::memory_order_acquire))
      continue;
    if (path == slot.path) {
      slot.state.store(kFree, std::memory_order_release);
      return;
    }
    slot.state.store(kStaged, std::memory_order_release);
  }
}

void removeStagedFile(const std::string& path) {
  std::remove(path.c_str());
  untrackStagedFile(path);
}

int renameStagedFile(const std::string& path, const std::string& to) {
  const int status = std::rename(path.c_str(), to.c_str());
  if (status == 0) {
    const int saved = errno;
    untrackStagedFile(path);
    errno = saved;
  }
  return status;
}

std::size_t stagedFileCount() {
  std::size_t count = 0;
  for (const Slot& slot : slots) {
    const int state = slot.state.load(std::memory_order_acquire);
    count += state == kStaged || state == kComparing;
  }
  return count;
}

void removeStagedFilesOnSignals() {
  struct sigaction action = {};
  action.sa_handler = removeAndDie;
  sigemptyset(&action.sa_mask);
  // Not the others while one runs: each would unlink and re-raise on its own.
  for (const int signal_number : {SIGINT, SIGTERM, SIGHUP})
    sigaddset(&action.sa_mask, signal_number);
  // A file size limit (ulimit -f) would end the process by SIGXFSZ at the write that crosses it,
  // leaving its staged files (review 167); ignored, that write fails with EFBIG, which the
  // writers report, naming the file, and clean up after (atomic_file.h, mat_file.h).
  std::signal(SIGXFSZ, SIG_IGN);
  for (const int signal_number : {SIGINT, SIGTERM, SIGHUP}) {
    // An ignored signal stays ignored (a job a shell started in the background ignores SIGINT,
    // nohup SIGHUP): the handler would make it end the process.
    struct sigaction old = {};
    if (::sigaction(signal_number, nullptr, &old) == 0 && old.sa_handler == SIG_IGN)
      continue;
    ::sigaction(signal_number, &action, nullptr);
  }
}

}  // namespace io
}  // namespace tracked_vehicle_dynamics
