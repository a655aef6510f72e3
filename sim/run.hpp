// A whole run: steps the state, hands a telemetry sample to the caller every
// `steps_per_sample` steps (scheduled by step count, not by comparing times) and
// watches for the first spin reversal and for divergence (NaN, inf, or energy growth).
#pragma once

#include <functional>
#include <optional>
#include <string>

#include "sim/model.hpp"
#include "sim/telemetry.hpp"

namespace sim {

struct RunOptions {
  std::int64_t steps_per_sample = 1;
  std::function<void(const Telemetry&)> on_sample;        ///< may be empty
  std::function<void(std::int64_t step)> on_progress;     ///< called every ~1% of the run
};

struct RunSummary {
  Telemetry first, last;
  /// First sign change of n that goes on to reach 1% of the initial spin the other way, s
  /// (the zero crossing, linearly interpolated).
  std::optional<double> first_reversal_s;
  std::int64_t steps = 0;
  double wall_s = 0;                        ///< wall-clock time of the stepping, s
  /// Set when the run stopped: a quantity became NaN or infinite, or the energy rose beyond
  /// what the model can supply. Names the quantity, the time and the step.
  std::optional<std::string> divergence;
};

/// Runs model.steps steps from `s` (which it advances).
RunSummary run(const Model& model, State& s, const RunOptions& options);

}  // namespace sim
