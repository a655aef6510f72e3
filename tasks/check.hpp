// `simulate --check` (docs/commands.md "The error of your own run: --check"): the error of the
// user's own run, estimated by running the same scene again at a tighter setting, half the step (or
// a hundredth of the tolerance), and comparing the two where it matters: each reversal time and the
// spin n(t) at the samples.
#pragma once

#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "sim/model.hpp"
#include "sim/rollout.hpp"

namespace tasks {

/// The tighter run of a check: the model, a phrase for it, and the order p of the method
/// when the step is fixed (Richardson: the run's error ≈ (run − tighter) · 2^p / (2^p − 1)).
struct TighterSetting {
  sim::Model model;
  std::string description;   ///< e.g. "rk4 at dt 0.00025 s (half the step)"
  std::optional<int> order;  ///< fixed steps only
};
TighterSetting tighterOf(const sim::Model& model);

/// The estimated errors of a run.
struct RunCheck {
  std::string setting;  ///< TighterSetting::description
  std::string method;   ///< "Richardson, order p" or "difference from the tighter run"
  /// Per reversal of the run, in order: its estimated error (run − truth), s; none for a
  /// reversal the tighter run does not have.
  std::vector<std::optional<double>> reversal_errors;
  std::vector<double> tighter_reversals;  ///< s
  double spin_error = 0;     ///< largest estimated |error| of n over the samples, rad/s
  double spin_error_at = 0;  ///< where, s
  double cost_ratio = 0;     ///< the tighter run's wall time over the run's
  bool completed = true;     ///< false: the tighter run stopped (then only what it reached)
};

/// Runs the tighter setting of `model`, sampling at `rate`, and compares it with the run's
/// summary and its spins at the samples (`spins[k]` at sampleTimes(duration, rate)[k]). Empty
/// when `cancelled` says so.
std::optional<RunCheck> checkRun(const sim::Model& model, double rate, const sim::RunSummary& run,
                                 const std::vector<double>& spins,
                                 const std::function<bool()>& cancelled = {});

/// The check as the sidecar's "check" object.
nlohmann::json checkJson(const RunCheck& check);

}  // namespace tasks
