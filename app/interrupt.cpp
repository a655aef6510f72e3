#include "app/interrupt.hpp"

#include <unistd.h>

#include <atomic>
#include <csignal>
#include <ctime>

#include "tasks/output.hpp"

namespace app {
namespace {

std::atomic<int> received{0};
std::atomic<long long> first_at_ns{0};  ///< when the first signal came, CLOCK_MONOTONIC

// A second signal this soon after the first is the same request delivered twice: `timeout -s
// INT` signals the program and then its whole process group (the program again), microseconds
// apart, and ending at once then had left 4 sweeps of 10 stopped with nothing said. A person's
// second Ctrl-C comes later than this.
constexpr long long kSameRequestNs = 100'000'000;

long long nowNs() {
  timespec now{};
  ::clock_gettime(CLOCK_MONOTONIC, &now);  // async-signal-safe (POSIX)
  return static_cast<long long>(now.tv_sec) * 1'000'000'000LL + now.tv_nsec;
}

extern "C" void onSignal(int signal) {
  const long long now = nowNs();
  if (received.load() == 0) {
    first_at_ns.store(now);
    received.store(signal);
    return;
  }
  if (now - first_at_ns.load() < kSameRequestNs) return;
  // The second: no more waiting.
  tasks::removeTemporaryFilesNow();
  ::_exit(128 + signal);
}

}  // namespace

void installInterruptHandlers() {
  struct sigaction action {};
  action.sa_handler = onSignal;
  // Each handler runs with both signals held back: a SIGTERM does not land inside a SIGINT's.
  sigemptyset(&action.sa_mask);
  sigaddset(&action.sa_mask, SIGINT);
  sigaddset(&action.sa_mask, SIGTERM);
  // A signal the program was started ignoring stays ignored: a shell starts a script's
  // background jobs (`rattleback … &`) with SIGINT ignored, so that the terminal's Ctrl-C stops
  // the script and not them (POSIX's "asynchronous lists"), as Python's rattleback and most
  // tools keep it.
  for (const int signal : {SIGINT, SIGTERM}) {
    struct sigaction before {};
    if (sigaction(signal, nullptr, &before) == 0 && before.sa_handler == SIG_IGN) continue;
    sigaction(signal, &action, nullptr);
  }
}

int interruptSignal() {
  return received.load();
}

int interruptedStatus() {
  return 128 + received.load();
}

}  // namespace app
