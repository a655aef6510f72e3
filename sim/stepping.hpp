// The steps of a run, as a unit of its own (docs/design.md "Data flow"): a Rollout keeps the run
// (its model, the watchdog, the reversal rule, the summary) and asks this for the steps, which
// tests then drive without a run. It holds the two ends of the last step, the states between them
// (sim::StepInterpolant) and, for an adaptive method (docs/physics.md P3.3), the stepper with the
// counts of the steppers it replaced. It takes the fixed method's step or the adaptive stepper's
// next accepted one, and starts the stepper afresh where a run's state is set or its contact model
// changes. The Rollout says when to step and in which contact model (auto's modes change).
#pragma once

#include <cstdint>
#include <memory>

#include "sim/model.hpp"
#include "sim/step_interpolant.hpp"

namespace sim {

class AdaptiveStepper;

class Stepping {
 public:
  /// Steps of `active` from `start` (its t and step kept): the fixed method's, or an adaptive
  /// stepper's when `active.integrator` is adaptive. The last step has no length yet.
  Stepping(const Model& active, const State& start);
  /// Goes on alone from where `other` is: the same ends and counts, and a copy of its adaptive
  /// stepper (step size and dense output).
  Stepping(const Stepping& other);
  Stepping& operator=(const Stepping&) = delete;
  Stepping(Stepping&&) noexcept;
  Stepping& operator=(Stepping&&) noexcept;
  ~Stepping();

  bool adaptive() const { return adaptive_ != nullptr; }
  /// The start of the last step.
  const State& previous() const { return previous_; }
  /// The end of the last step: the latest state.
  const State& current() const { return current_; }

  /// Takes one step: the adaptive stepper's next accepted one (the quaternion renormalised;
  /// the stepper integrates the model it was started in), else the fixed method's step of
  /// `active`, ending at t = (step + 1)·dt.
  void step(const Model& active);
  /// Takes one fixed step of dt (s) whose end `advance(State& s, double t_end)` reaches in
  /// place of the method (auto sliding: the smooth contact in steps of its own,
  /// AutoSwitch::advance); it ends at t = (step + 1)·dt as step() does.
  template <typename Advance>
  void stepBy(double dt, Advance&& advance);

  /// Goes on from `s` (its t and step as given): a last step of no length at s, and an adaptive
  /// stepper started afresh there in `active`.
  void startFrom(const Model& active, const State& s);
  /// The last step was cut at t_cut (s) by a change of contact model: before t_cut its states
  /// are those of `before`'s step, which ended at current(). Then endAt() gives its new end.
  void cut(double t_cut, const Model& before);
  /// The last step ends at `end` instead (in `active`, after a cut): an adaptive stepper starts
  /// afresh there, and the step is then interpolated by Hermite.
  void endAt(const Model& active, const State& end);

  /// The state at time t (s) within the last step, integrated in `active`: the steps' own
  /// states at their ends (stamped with t); between them the adaptive stepper's dense output or
  /// a cubic Hermite interpolant (sim/step_interpolant.hpp), with the quaternion renormalised
  /// and, under rolling, the state put back on the constraint.
  State stateAt(double t, const Model& active) const;
  /// The spin n = ω·ẑ (rad/s) at time t (s) within the last step, integrated in `active`, on
  /// the interpolant (StepInterpolant::spinAt): what the reversal rule reads between the ends.
  double spinAt(double t, const Model& active) const {
    return last_step_.spinAt(t, active, previous_, current_, adaptive_.get());
  }
  /// The contact model the last step was integrated in at time t (s): `active`, or the model
  /// before a cut for times before it.
  const Model& modeAt(double t, const Model& active) const { return last_step_.modeAt(t, active); }

  /// Adaptive: evaluations of the equations of motion by this stepper and every one before it.
  std::int64_t evaluations() const;
  /// Adaptive: steps tried and rejected by error control, by this stepper and every one before.
  std::int64_t rejected() const;

 private:
  /// Adaptive: a new stepper from current_ in `active`, its predecessor's counts kept.
  void restart(const Model& active);

  /// Adaptive: what the steppers before the current one did.
  struct EarlierSteppers {
    std::int64_t evaluations = 0, rejected = 0;
    std::int64_t start_step = 0;  ///< the step the current stepper started at
  };

  State previous_, current_;   ///< the last step's ends
  StepInterpolant last_step_;  ///< states between them
  std::unique_ptr<AdaptiveStepper> adaptive_;
  EarlierSteppers earlier_;
};

template <typename Advance>
void Stepping::stepBy(double dt, Advance&& advance) {
  previous_ = current_;
  const std::int64_t index = current_.step + 1;
  advance(current_, static_cast<double>(index) * dt);
  current_.step = index;
  current_.t = static_cast<double>(index) * dt;
  last_step_.stepTaken();
}

}  // namespace sim
