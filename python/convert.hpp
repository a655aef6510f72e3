// Between the library's values and Python's: JSON values as dicts and lists, errors as the
// package's exceptions, and long calls that release the GIL and stop on Ctrl-C.
#pragma once

#include <pybind11/pybind11.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <ctime>
#include <functional>
#include <mutex>
#include <nlohmann/json.hpp>
#include <thread>

#include "util/result.hpp"

namespace pyrb {

namespace py = pybind11;

/// A JSON value as the Python object json.loads would give of its text (null → None, and so
/// a non-finite number, which the files write as null, is None too).
inline py::object toPython(const nlohmann::json& j) {
  switch (j.type()) {
    case nlohmann::json::value_t::null:
      return py::none();
    case nlohmann::json::value_t::boolean:
      return py::bool_(j.get<bool>());
    case nlohmann::json::value_t::number_integer:
      return py::int_(j.get<std::int64_t>());
    case nlohmann::json::value_t::number_unsigned:
      return py::int_(j.get<std::uint64_t>());
    case nlohmann::json::value_t::number_float: {
      const double v = j.get<double>();
      return std::isfinite(v) ? py::object(py::float_(v)) : py::object(py::none());
    }
    case nlohmann::json::value_t::string:
      return py::str(j.get<std::string>());
    case nlohmann::json::value_t::array: {
      py::list list;
      for (const auto& e : j) list.append(toPython(e));
      return list;
    }
    case nlohmann::json::value_t::object: {
      py::dict dict;
      for (const auto& [k, v] : j.items()) dict[py::str(k)] = toPython(v);
      return dict;
    }
    default:
      return py::none();
  }
}

/// Raises rattleback.SceneError (a ValueError) for an error in a scene, with its file, line
/// and key; ValueError for any other bad input; OSError for an error of the machine.
[[noreturn]] inline void raise(const rb::Error& error) {
  const std::string message = error.text();
  if (error.machine) {  // a full disk, no OpenGL: the command line's exit status 4
    PyErr_SetString(PyExc_OSError, message.c_str());
    throw py::error_already_set();
  }
  if (error.where) {
    py::object cls = py::module_::import("rattleback._errors").attr("SceneError");
    py::object line = error.where->line > 0 ? py::object(py::int_(error.where->line)) : py::none();
    py::object e = cls(
        message, error.where->file, line,
        error.where->key.empty() ? py::object(py::none()) : py::object(py::str(error.where->key)));
    PyErr_SetObject(cls.ptr(), e.ptr());
    throw py::error_already_set();
  }
  throw py::value_error(message);
}

template <typename T>
T take(rb::Result<T> result) {
  if (!result) raise(result.error());
  return std::move(result).value();
}

/// Whether this is Python's main thread, the only one signals reach (the GIL held). Elsewhere (a
/// worker of a ThreadPoolExecutor, a daemon thread) a run never takes the GIL to look for them:
/// PyErr_CheckSignals would find none there, and a daemon thread that takes the GIL after the
/// interpreter began to exit is ended by CPython in the middle of our code (std::terminate, exit
/// 134 when a script ended with a run going on).
inline bool onMainThread() {
  const py::module_ threading = py::module_::import("threading");
  const py::object main = threading.attr("main_thread")().attr("ident");
  return main.equal(threading.attr("get_ident")());
}

/// The GIL released for a run, and taken back after, unless the interpreter is exiting: then
/// this thread (a daemon thread still running at exit) waits for the process to end, as
/// CPython's own daemon threads do, rather than be ended inside a destructor.
class GilReleased {
  static bool finalizing() {
#if PY_VERSION_HEX >= 0x030D0000
    return Py_IsFinalizing();  // public from Python 3.13
#else
    return _Py_IsFinalizing();
#endif
  }

 public:
  GilReleased() : state_(PyEval_SaveThread()) {}
  ~GilReleased() {
    while (finalizing()) std::this_thread::sleep_for(std::chrono::seconds(1));
    PyEval_RestoreThread(state_);
  }
  GilReleased(const GilReleased&) = delete;
  GilReleased& operator=(const GilReleased&) = delete;

 private:
  PyThreadState* state_;
};

/// Runs `work(cancelled)` on this thread with the GIL released, for work that asks
/// `cancelled()` on the calling thread (a run's samples, a sweep's pool's wait): there, at most
/// every 20 ms, it takes the GIL and checks for signals (PyErr_CheckSignals acts on the main
/// thread only). On Ctrl-C `cancelled()` turns true; once the work has returned (its temporary
/// files removed) KeyboardInterrupt is raised here, with what the work returned handed to
/// `keep` (a sweep's finished rows: the exception's attribute `table`). No thread is made: a
/// short call costs nothing more than the GIL's release.
template <typename Work, typename Keep>
auto interruptibleHere(Work&& work, Keep&& keep) {
  std::atomic<bool> stop{false};
  bool signalled = false;
  PyObject *type = nullptr, *value = nullptr, *trace = nullptr;
  const std::thread::id caller = std::this_thread::get_id();
  const bool main = onMainThread();
  // The coarse clock (a few ms fine, a few ns to read): asked before every sample, the fine
  // one's clock_gettime was 8 % of a 10 kHz run's time.
  const auto coarseMs = [] {
    timespec now{};
    clock_gettime(CLOCK_MONOTONIC_COARSE, &now);
    return static_cast<std::int64_t>(now.tv_sec) * 1000 + now.tv_nsec / 1000000;
  };
  std::int64_t last = coarseMs();
  const std::function<bool()> cancelled = [&] {
    if (stop.load(std::memory_order_relaxed)) return true;
    if (!main || std::this_thread::get_id() != caller) return false;
    const std::int64_t now = coarseMs();
    if (now - last < 20) return false;
    last = now;
    py::gil_scoped_acquire acquire;
    if (PyErr_CheckSignals() != 0) {
      PyErr_Fetch(&type, &value, &trace);  // kept while the work winds down
      signalled = true;
      stop = true;
    }
    return stop.load();
  };
  using R = decltype(work(cancelled));
  std::optional<R> result;
  {
    GilReleased release;
    result.emplace(work(cancelled));
  }
  if (signalled) {
    PyErr_NormalizeException(&type, &value, &trace);
    if (value) keep(py::handle(value), std::move(*result));
    PyErr_Restore(type, value, trace);
    throw py::error_already_set();
  }
  return std::move(*result);
}

template <typename Work>
auto interruptibleHere(Work&& work) {
  return interruptibleHere(std::forward<Work>(work), [](py::handle, auto&&) {});
}

/// Runs `work(cancelled)` on a thread of its own with the GIL released, while this thread
/// checks for signals every 20 ms (PyErr_CheckSignals needs the GIL and the main thread).
/// On Ctrl-C `cancelled()` turns true; the work stops at its next sample or frame, and once it
/// has returned (its temporary files removed) KeyboardInterrupt is raised here. The thread is
/// joined before returning: none outlives the call.
template <typename Work>
auto interruptible(Work&& work) {
  std::atomic<bool> stop{false};
  const std::function<bool()> cancelled = [&stop] { return stop.load(std::memory_order_relaxed); };
  using R = decltype(work(cancelled));
  std::optional<R> result;
  std::exception_ptr failure;
  std::mutex mutex;
  std::condition_variable finished;
  bool done = false;
  const bool main = onMainThread();
  {
    GilReleased release;
    std::thread worker([&] {
      try {
        result.emplace(work(cancelled));
      } catch (...) {
        failure = std::current_exception();
      }
      std::lock_guard lock(mutex);
      done = true;
      finished.notify_one();
    });
    // Wakes when the work ends, or every 20 ms to look for a signal.
    std::unique_lock lock(mutex);
    // (Off the main thread no signal comes: the work is waited for.)
    while (!finished.wait_for(lock, std::chrono::milliseconds(main ? 20 : 1000),
                              [&] { return done; })) {
      if (!main) continue;
      lock.unlock();
      bool signalled = false;
      PyObject *type = nullptr, *value = nullptr, *trace = nullptr;
      {
        py::gil_scoped_acquire acquire;
        if (PyErr_CheckSignals() != 0) {
          signalled = true;
          PyErr_Fetch(&type, &value, &trace);  // kept while the work winds down
        }
      }
      if (signalled) {
        stop = true;
        worker.join();  // the work stops at its next sample or frame
        py::gil_scoped_acquire acquire;
        PyErr_Restore(type, value, trace);
        throw py::error_already_set();
      }
      lock.lock();
    }
    lock.unlock();
    worker.join();
  }
  if (failure) std::rethrow_exception(failure);
  return std::move(*result);
}

}  // namespace pyrb
