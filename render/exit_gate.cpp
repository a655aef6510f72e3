#include "render/exit_gate.hpp"

#include <chrono>
#include <condition_variable>
#include <cstdlib>
#include <mutex>
#include <thread>

namespace render {
namespace {

struct Gate {
  std::mutex mutex;
  std::condition_variable idle;
  int in_hand = 0;  // outermost GlWork objects alive, over all threads
  bool closing = false;
  std::thread::id exiting;  // the thread running exit(): it is never parked
};

// Never destroyed: exit handlers and threads still use it while statics are torn down.
Gate& gate() {
  static Gate* const g = new Gate;
  return *g;
}

thread_local int depth = 0;  // GlWork objects alive on this thread

void closeAtExit() {
  Gate& g = gate();
  std::unique_lock lock(g.mutex);
  g.closing = true;
  g.exiting = std::this_thread::get_id();
  // A frame at 4K with llvmpipe takes about a second; past 10 s something else is stuck, and
  // waiting longer would turn a crash at exit into a hang.
  g.idle.wait_for(lock, std::chrono::seconds(10), [&] { return g.in_hand == depth; });
}

}  // namespace

GlWork::GlWork() {
  if (depth++ > 0) return;
  Gate& g = gate();
  std::unique_lock lock(g.mutex);
  if (g.closing && g.exiting != std::this_thread::get_id()) {
    lock.unlock();
    for (;;) std::this_thread::sleep_for(std::chrono::hours(1));
  }
  ++g.in_hand;
}

GlWork::~GlWork() {
  if (--depth > 0) return;
  Gate& g = gate();
  std::lock_guard lock(g.mutex);
  if (--g.in_hand == 0 || g.closing) g.idle.notify_all();
}

void holdExitForGlWork(Backend backend) {
  static std::once_flag egl, osmesa;
  std::call_once(backend == Backend::OsMesa ? osmesa : egl, [] { std::atexit(closeAtExit); });
}

}  // namespace render
