// The reversal rule (docs/physics.md P7), the program's headline number, as a unit of its own:
// fed the spin n = ω·ẑ over each step (its ends, and n(t) between them on the integrator's
// interpolant), it finds the zero crossings that are reversals. A Rollout feeds it; tests feed
// it scripted n(t) directly.
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
  /// While a crossing is pending, n is read at this many equal parts of each step (and at
  /// each extreme between them): the rule's tests then hold at the times n meets the
  /// thresholds, not at the step ends, so the reversal does not depend on where steps end.
  static constexpr int kSamples = 8;
  /// …but at parts no shorter than this, s: a shorter step is read at its ends only. Its ends
  /// are then this close or closer, and n is not read more finely than it is stepped where
  /// steps are short (a points-model body stepped every 10 µs is pending for most of its run
  /// while lying still, and reading each step 8 times cost it 1.7× its CPU).
  static constexpr double kFinestRead = 1e-4;

  /// `initial_spin`: n at the start, rad/s (0: nothing can reverse).
  explicit ReversalDetector(double initial_spin);

  /// One step from t0 to t1 (s) with n0 and n1 at its ends (rad/s); `n_at(t)` is n at a time
  /// within the step (the integrator's interpolant), rad/s, asked for only when n changes sign
  /// against the reference or a crossing is pending. `last_flight` is the last time the body
  /// was in the air, s; `at_end` says the step reached the run's end, where a crossing that has
  /// reached kFraction within kHoldTime of it counts without the rest of the hold.
  void step(double t0, double n0, double t1, double n1, double last_flight, bool at_end,
            const std::function<double(double)>& n_at);

  /// The reversals so far, s.
  const std::vector<double>& reversals() const { return reversals_; }

 private:
  /// Where the rule stands: no candidate; a candidate crossing with n on the new side but not
  /// yet beyond the threshold; a candidate that has reached the threshold.
  enum class Phase { Idle, Crossed, Reached };
  /// The rule from time t (n there: nt) to the step's end, on m = n·reference sign.
  void follow(double t, double nt, double t1, double n1, const std::function<double(double)>& m_at);
  /// The candidate is a reversal: counted, and the next is counted from the new sign.
  void count();

  double threshold_;               ///< rad/s
  double reference_sign_;          ///< the sign being reversed from (±1; 0: none)
  Phase phase_ = Phase::Idle;      ///< what `crossing_` is
  double crossing_ = 0;            ///< the candidate: the last crossing to the other sign, s
  double last_flight_ = -1e300;    ///< s, as given with the step being followed
  std::vector<double> reversals_;  ///< s
};

}  // namespace sim
