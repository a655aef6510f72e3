// The reversal rule (docs/physics.md P7), the program's headline number, as a unit of its own:
// fed the spin n = ω·ẑ at the ends of each step, it finds the zero crossings that are reversals.
// A Rollout feeds it; tests feed it scripted n(t) directly.
#pragma once

#include <functional>
#include <optional>
#include <vector>

namespace sim {

class ReversalDetector {
 public:
  /// A crossing counts once n has gone on to reach this fraction of the initial |n| the new way.
  static constexpr double kFraction = 0.01;
  /// …and is beyond that fraction the new way again this long or more after the crossing, s,
  /// not having gone back beyond it the old way (a body rocking through tens of degrees swings
  /// n through zero and back within a rocking period: 0.14–0.29 s for the default body).
  static constexpr double kHoldTime = 0.2;
  /// …and not within this long of a flight, s (a dropped body wobbles through n = 0 while it
  /// bounces: about 0.6 s from 5 cm at 30°).
  static constexpr double kSettleTime = 0.5;

  /// `initial_spin`: n at the start, rad/s (0: nothing can reverse).
  explicit ReversalDetector(double initial_spin);

  /// One step from t0 to t1 (s) with n0 and n1 at its ends (rad/s). `locate()` gives the time
  /// of the zero crossing within the step (on the integrator's interpolant); it is called only
  /// when n changes sign against the reference. `last_flight` is the last time the body was in
  /// the air, s; `at_end` says the step reached the run's end, where a crossing that has reached
  /// kFraction within kHoldTime of it counts without the rest of the hold.
  void step(double t0, double n0, double t1, double n1, double last_flight, bool at_end,
            const std::function<double()>& locate);

  /// The reversals so far, s.
  const std::vector<double>& reversals() const { return reversals_; }

 private:
  double threshold_;                ///< rad/s
  double reference_sign_;           ///< the sign being reversed from (±1; 0: none)
  std::optional<double> crossing_;  ///< the candidate: the last crossing to the other sign
  bool crossing_reached_ = false;   ///< n has reached the threshold since crossing_
  std::vector<double> reversals_;
};

}  // namespace sim
