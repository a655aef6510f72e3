// A run the caller pulls (docs/design.md "Data flow"): a Rollout advances a Model from a state,
// step by step, only as far as the caller asks, and gives the state at any time inside its last
// step — so frames and telemetry samples fall at exact times whatever the step. It watches the run
// as it goes: spin reversals, NaN or infinity, energy from nowhere, a rolling body on its rim, and
// a stop request. It makes no threads and calls nothing back.
#pragma once

#include <limits>
#include <optional>
#include <stop_token>
#include <string>
#include <vector>

#include "sim/auto_switch.hpp"
#include "sim/model.hpp"
#include "sim/reversals.hpp"
#include "sim/stepping.hpp"
#include "sim/telemetry.hpp"
#include "sim/watchdog.hpp"

namespace sim {

/// What a run did so far.
struct RunSummary {
  Telemetry first, last;  ///< at the start, and at the last time sampled or reached
  /// Spin reversals (docs/physics.md P7), s: each is a zero crossing of n = ω·ẑ,
  /// located on the interpolant between steps, after which n goes on to reach 1% of the
  /// initial |n| with the new sign and keeps that sign for 0.2 s (a body rocking through tens
  /// of degrees swings n through zero and back), at least 0.5 s after the body last left the
  /// floor for 10 ms or more (no reversals in the air or while it bounces). The next is counted
  /// from the new sign. At the end of the run a crossing that has reached 1% counts without the 0.2
  /// s.
  std::vector<double> reversals;
  std::optional<double> first_reversal_s;  ///< reversals.front(), when there is one
  /// Largest tilt of the body's z axis from the vertical at the start or the end of any step
  /// so far, degrees.
  double max_tilt_deg = 0;
  std::int64_t steps = 0;        ///< accepted steps
  std::int64_t rejected = 0;     ///< adaptive: steps tried and rejected by error control
  std::int64_t evaluations = 0;  ///< adaptive: evaluations of the equations of motion
  double wall_s = 0;             ///< wall-clock time spent stepping, s
  /// Set when the run stopped by itself: a quantity became NaN or infinite, the energy rose
  /// beyond what the model can supply, or a rolling body tipped onto its rim. Names the
  /// quantity, the time and the step.
  std::optional<std::string> divergence;
  std::optional<Stop> stop;     ///< set with `divergence`: the same event, typed
  bool stop_requested = false;  ///< stopped because the caller asked
  /// contact.model auto: how many times the model changed, and when to which.
  int switches = 0;
  std::vector<std::pair<double, ContactModel>> mode_changes;
  /// contact.model rolling: the first time sampled at which the constraint needed the floor to
  /// pull the body down (normal force below 0, where a real body lifts off; rolling holds it to
  /// the floor regardless, docs/physics.md P4.5). Set by the sampler (tasks::simulate), from the
  /// samples' normal force, which they compute anyway: not looked for between samples.
  std::optional<double> floor_pulled_s;
  /// contact.model rolling: the first time sampled at which the constraint needed more friction
  /// than the floor gives (|F_t| > μN with N > 0, where a real body slips), and the most it
  /// needed, max |F_t|/N over the samples with N > 0 (NaN when none). Set by the sampler, as
  /// floor_pulled_s is.
  std::optional<double> friction_exceeded_s;
  double friction_needed = std::numeric_limits<double>::quiet_NaN();
};

class Rollout {
 public:
  /// Starts `model` from its initial state (docs/physics.md P5).
  explicit Rollout(Model model);
  /// Starts `model` from `start` (its t and step are kept).
  Rollout(Model model, State start);
  /// A run that goes on alone from where `other` is: the same states, stepper, summary and
  /// reversal rule, and a stop request of its own (a stopWith token is not carried over).
  Rollout(const Rollout& other);
  Rollout& operator=(const Rollout&) = delete;
  Rollout(Rollout&&) noexcept;
  Rollout& operator=(Rollout&&) noexcept;
  ~Rollout();

  const Model& model() const { return model_; }
  /// The contact model being integrated now (under auto: rolling or smooth).
  ContactModel mode() const { return active_.contact.model; }
  /// The latest state reached: the end of the last step.
  const State& current() const { return steps_.current(); }
  /// The end of the run: model.duration, s.
  double endTime() const { return model_.duration; }

  /// Steps until the state reaches time t (current().t ≥ t). False when the run has stopped
  /// (divergence or stop request) before reaching it; then summary() says why.
  bool advanceTo(double t);
  /// Steps as advanceTo(t) does, and stops too after the step at which the reversal rule
  /// confirms a reversal (reversals() grows): the steps are advanceTo's, so what is known when it
  /// stops is what a run to t knows at that step. False when the run has stopped before either.
  bool advanceToReversal(double t);
  /// Takes one step (the fixed dt, or the adaptive stepper's next accepted one). False, and
  /// no step taken, when the run has stopped. summary().last is then the step's end.
  bool advanceOneStep();
  /// Adaptive steps only: the next step that would pass `t` (s) ends at t instead, and the
  /// stepper starts again there (as after a change of mode), so that current().t is t and a
  /// setState() acts at t; the steps after it differ from those a run not stopped there takes,
  /// within the tolerance. Reached, or given nothing, it stops nothing more. Fixed steps end at
  /// multiples of dt and are not cut: landAt() is then refused (false).
  bool landAt(std::optional<double> t);
  /// Goes on from `s` instead of the current state, at the current time and step (s.t and
  /// s.step are not read), as if the body were struck there: under rolling s is put back on
  /// the constraint (its height and velocity follow from ω); under auto the mode is chosen
  /// again as at the start; an adaptive stepper starts afresh from s; the watchdog measures
  /// energy from s's (a tap adds energy no step did). Reversals go on being counted from the
  /// sign they had, with the initial spin's threshold.
  void setState(State s);

  /// The state at time t, which must lie within the last step [previous().t, current().t]
  /// (what advanceTo(t) leaves): the steps' own states at their ends; between them the
  /// integrator's dense output (adaptive) or a cubic Hermite interpolant (fixed steps), with
  /// the quaternion renormalised and, under rolling, the state put back on the constraint.
  State stateAt(double t) const;
  /// Telemetry at time t (as stateAt). No side effects: sampling at any times of the last step,
  /// in any order, leaves the run and its summary as they are.
  Telemetry sampleAt(double t) const;

  /// Stops the run at its next step; safe from another thread.
  void requestStop() { stop_.own.request_stop(); }
  /// Stops the run when `token` is stopped (e.g. a std::jthread's or a signal handler's).
  void stopWith(std::stop_token token) { stop_.external = std::move(token); }
  bool stopped() const { return summary_.divergence.has_value() || summary_.stop_requested; }

  /// The reversals so far (as summary().reversals, without sampling the last time), s.
  const std::vector<double>& reversals() const { return summary_.reversals; }
  /// The start of the last step, s (current().t before its last step; the same at the start).
  double previousTime() const { return steps_.previous().t; }

  /// What the run did so far; its `last` is the telemetry at the time the last advanceTo asked
  /// for (or where the run stopped, when it stopped before it).
  const RunSummary& summary() const;
  /// Wall-clock time spent stepping so far, s: summary().wall_s without sampling the last time
  /// (for a budget checked at every sample).
  double wallSeconds() const { return summary_.wall_s; }

 private:
  void stepOnce();
  /// landAt(): the step just taken ends at land_at_ if it passed it (before anything reads it).
  void land();
  /// advanceTo(t), or advanceToReversal(t) when `until_reversal`.
  bool advance(double t, bool until_reversal);
  /// Feeds the watchdog the end of the last step (its rotation R and ω w, world axes);
  /// records its stop.
  void watch(const Eigen::Matrix3d& R, const Eigen::Vector3d& w);
  /// Whether the run stops where the lowest point leaves the smooth surface (docs/physics.md
  /// P6): rolling at a paraboloid's rim; every smooth model (smooth, rolling, auto) at the edge
  /// of a mesh's fitted bottom, beyond which there is no smooth surface to slide on either.
  bool stopsOnRim() const;
  void locateReversal(double previous_spin, double spin);
  /// Auto: after each step, carries out a change of mode the switch calls for.
  void switchModes();
  /// Carries out a change found in the last step: fixed steps finish the step in the new mode;
  /// adaptive ones restart there.
  void changeMode(ModeChange change);
  /// Steps that this many steps apart are watched (about once per simulated millisecond;
  /// every step when adaptive).
  std::int64_t checkEvery() const;
  void countSteps() const;  ///< the summary's steps, tilt and evaluations, as they are now

  /// What stops the run when asked: requestStop() (a source of its own) or stopWith()'s token.
  struct StopRequests {
    std::stop_source own;
    std::stop_token external;
    bool requested() const { return own.stop_requested() || external.stop_requested(); }
  };

  Model model_;                     ///< the run as compiled
  std::optional<AutoSwitch> auto_;  ///< contact.model auto: when its mode changes
  Model active_;  ///< the model being integrated: model_, or under auto its rolling or smooth mode
  Stepping steps_;  ///< the last step's ends, the states between them, the adaptive stepper
  StopRequests stop_;
  mutable RunSummary summary_;  ///< `last` is filled in when asked for (summary())
  /// The time of summary().last, s, while it is still to be sampled.
  mutable std::optional<double> last_due_s_;
  ReversalDetector reversals_{0};  ///< the reversal rule, fed each step and its interpolant
  double spin_ = 0;                ///< n = ω·ẑ of current(), rad/s
  double min_cos_tilt_ = 1;        ///< smallest cosine of the tilt so far
  Watchdog watchdog_;              ///< NaN, energy from nowhere, the rim; and the last flight
  std::optional<double> land_at_;  ///< landAt(): the time the next step passing it ends at, s
};

/// Sample times of a run of `duration` s at `rate` samples per simulated second:
/// t_k = k / rate for k = 0, 1, … while t_k ≤ duration, and the end itself when it is not one
/// of them.
std::vector<double> sampleTimes(double duration, double rate);

/// Runs `rollout` to its end, pulling a sample at each of sampleTimes(end, rate) and handing it
/// to `each` (may be empty). Returns the summary.
template <typename Each>
const RunSummary& sampleRun(Rollout& rollout, double rate, Each&& each) {
  for (double t : sampleTimes(rollout.endTime(), rate)) {
    if (!rollout.advanceTo(t)) break;
    const Telemetry sample = rollout.sampleAt(t);
    each(sample);
  }
  return rollout.summary();
}

}  // namespace sim
