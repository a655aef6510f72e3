// The state between the ends of a run's last step, as a unit of its own: the adaptive
// stepper's dense output, or a cubic Hermite interpolant of the whole state with its rates at
// both ends (x with v, v with v̇, q with q̇, L with τ). Its error is O(h⁴) for a smooth motion,
// below the integrators' own, and it hits both ends exactly (slerp would interpolate the
// rotation at only O(h²) and ignore ω). A step cut by a change of contact model (auto) is two
// pieces: before the change, the old mode's own step. A Rollout owns one; tests drive it on
// scripted step ends.
#pragma once

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>

#include "sim/model.hpp"
#include "sim/step.hpp"

namespace sim {

class AdaptiveStepper;

/// Times closer than this (relative) are the same time: a sample asked for at k/rate is the
/// step k·dt when the two differ only by rounding.
inline constexpr double kSameTime = 1e-12;

/// Whether a and b (s) are the same time up to rounding (kSameTime relative to b, or
/// absolute below 1 s).
inline bool sameTime(double a, double b) {
  return std::abs(a - b) <= kSameTime * std::max(1.0, std::abs(b));
}

/// The cubic Hermite interpolant at time t (s) between states a and b (a.t < b.t) with their
/// rates: each component y(t) = h00 y_a + h10 h ẏ_a + h01 y_b + h11 h ẏ_b with h = b.t − a.t.
/// The quaternion is not renormalised; t is set, and the step index is a's.
State hermite(const State& a, const Rates& rates_a, const State& b, const Rates& rates_b, double t);

class StepInterpolant {
 public:
  /// A new last step was taken: its rates at the ends are to be computed again, and the
  /// stepper's dense output covers it.
  void stepTaken();
  /// The adaptive stepper was restarted at the step's end: it has no dense output for the step
  /// just ended, which is interpolated by Hermite.
  void denseLost() { dense_lost_ = true; }
  /// The last step was cut at t_cut (s) by a change of contact model: before t_cut its states
  /// are those of `before`'s own step, from the step's start to `before_end`.
  void cut(double t_cut, const Model& before, const State& before_end);

  /// The model the last step was integrated in at time t (s): `before` of a cut for times
  /// before the cut, else `active`.
  const Model& modeAt(double t, const Model& active) const;

  /// The state at time t (s) within the last step [a.t, b.t], integrated in `active` (with its
  /// adaptive stepper `dense`, or null for fixed steps). Sets `on_constraint` (when given) to
  /// whether the state is on the rolling constraint already (the dense output of a rolling
  /// stepper). Neither renormalised nor put on a constraint otherwise.
  State at(double t, const Model& active, const State& a, const State& b,
           const AdaptiveStepper* dense, bool* on_constraint = nullptr) const;
  /// The spin n = ω·ẑ (rad/s) of at()'s state at time t: from the adaptive stepper's dense
  /// output without forming the whole state where at() would read it (the reversal rule reads
  /// n up to 8 times a step while a crossing is pending: a state each had been 8 % of a
  /// rolling run), else from at()'s state.
  double spinAt(double t, const Model& active, const State& a, const State& b,
                const AdaptiveStepper* dense) const;

 private:
  /// Whether time t of the last step (from a) falls before a cut inside it.
  bool beforeCut(const State& a, double t) const {
    return a.t < cut_s_ && t < cut_s_ && !sameTime(t, cut_s_);
  }
  /// Rates at the ends of the last step, packed as the state; computed when first needed.
  mutable bool have_rates_ = false;
  mutable Rates rates_a_{}, rates_b_{};
  bool dense_lost_ = false;  ///< adaptive: Hermite over the last step (a restart ended it)
  Model before_;             ///< the mode before the last cut
  State before_end_;         ///< and where its step ended before the cut
  double cut_s_ = -std::numeric_limits<double>::infinity();  ///< the last cut's time, s
};

}  // namespace sim
