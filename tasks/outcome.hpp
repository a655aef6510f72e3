// How a task's run ended, typed: what the front ends (the command line's exit status and message,
// Python's exceptions) decide on, instead of reading each other's text.
#pragma once

#include <optional>
#include <string>

#include "sim/rollout.hpp"

namespace tasks {

enum class Ending {
  Completed,    ///< ran to its end
  Stopped,      ///< stopped by itself (Outcome::stop says why, when and at which step)
  Interrupted,  ///< a stop was requested (Ctrl-C, a caller's stop token)
};

struct Outcome {
  Ending ending = Ending::Completed;
  std::optional<sim::Stop> stop;  ///< for Ending::Stopped
  std::string message;            ///< for Ending::Stopped: the run's own words
  double t = 0;                   ///< simulated time reached, s
  /// For Ending::Stopped: the first reversal the rule had counted before the stop, s (none if
  /// it had not reversed), so that a front end can say what the run found before it stopped.
  std::optional<double> first_reversal_s;
};

/// The outcome of a run from its summary.
inline Outcome outcomeOf(const sim::RunSummary& run) {
  Outcome o;
  o.t = run.last.t;
  if (run.divergence) {
    o.ending = Ending::Stopped;
    o.stop = run.stop;
    o.message = *run.divergence;
    if (!run.reversals.empty()) o.first_reversal_s = run.reversals.front();
  } else if (run.stop_requested) {
    o.ending = Ending::Interrupted;
  }
  return o;
}

}  // namespace tasks

namespace rb {
template <>
struct NameTable<tasks::Ending> {
  static constexpr std::array<std::pair<tasks::Ending, std::string_view>, 3> entries{{
      {tasks::Ending::Completed, "ok"},
      {tasks::Ending::Stopped, "stopped"},
      {tasks::Ending::Interrupted, "interrupted"},
  }};
};
}  // namespace rb
