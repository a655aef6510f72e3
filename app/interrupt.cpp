#include "app/interrupt.hpp"

#include <unistd.h>

#include <atomic>
#include <csignal>

#include "tasks/output.hpp"

namespace app {
namespace {

std::atomic<int> received{0};

extern "C" void onSignal(int signal) {
  if (received.exchange(signal) != 0) {  // the second: no more waiting
    tasks::removeTemporaryFilesNow();
    ::_exit(128 + signal);
  }
}

}  // namespace

void installInterruptHandlers() {
  struct sigaction action {};
  action.sa_handler = onSignal;
  sigemptyset(&action.sa_mask);
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
