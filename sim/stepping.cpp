#include "sim/stepping.hpp"

#include "sim/adaptive.hpp"
#include "sim/contact_model.hpp"
#include "sim/integrator.hpp"
#include "sim/step.hpp"

namespace sim {

Stepping::Stepping(const Model& active, const State& start)
    : previous_(start),
      current_(start),
      adaptive_(isAdaptive(active.integrator) ? std::make_unique<AdaptiveStepper>(active, start)
                                              : nullptr) {
  // A run started at a later step (Rollout's start kept its step) counts its stepper's accepted
  // steps from there: rejected() is its tries less those.
  earlier_.start_step = start.step;
}

Stepping::Stepping(const Stepping& other)
    : previous_(other.previous_),
      current_(other.current_),
      last_step_(other.last_step_),
      adaptive_(other.adaptive_ ? std::make_unique<AdaptiveStepper>(*other.adaptive_) : nullptr),
      earlier_(other.earlier_) {}

Stepping::Stepping(Stepping&&) noexcept = default;
Stepping& Stepping::operator=(Stepping&&) noexcept = default;
Stepping::~Stepping() = default;

void Stepping::step(const Model& active) {
  previous_ = current_;
  if (adaptive_) {
    current_ = adaptive_->step(current_.step + 1);
    // The integrator's own copy is not touched: the rates use q normalised. (Under rolling
    // the stepper integrates no z or v; its states come on the constraint.)
    current_.q.normalize();
  } else {
    sim::step(active, current_);  // which puts a rolling state back on the constraint itself
  }
  last_step_.stepTaken();
}

void Stepping::startFrom(const Model& active, const State& s) {
  previous_ = s;
  last_step_.stepTaken();  // a step of no length: its ends are s
  endAt(active, s);
}

void Stepping::cut(double t_cut, const Model& before) {
  last_step_.cut(t_cut, before, current_);
}

void Stepping::endAt(const Model& active, const State& end) {
  current_ = end;
  if (adaptive_) restart(active);
}

void Stepping::restart(const Model& active) {
  earlier_.evaluations += adaptive_->evaluations();
  earlier_.rejected += adaptive_->rejected(current_.step - earlier_.start_step);
  adaptive_ = std::make_unique<AdaptiveStepper>(active, current_);
  earlier_.start_step = current_.step;
  last_step_.denseLost();  // the new stepper has no dense output for the step just ended
}

State Stepping::stateAt(double t, const Model& active) const {
  // A time within rounding of a step is that step's own state (stamped with the time asked).
  for (const State* end : {&current_, &previous_}) {
    if (!sameTime(t, end->t)) continue;
    State s = *end;
    s.t = t;
    return s;
  }
  bool on_constraint = false;
  State s = last_step_.at(t, active, previous_, current_, adaptive_.get(), &on_constraint);
  if (on_constraint) return s;  // normalised and placed by the stepper (adaptive.cpp's Rolling)
  s.q.normalize();
  holdOnFloor(last_step_.modeAt(t, active), s);
  return s;
}

std::int64_t Stepping::evaluations() const {
  return adaptive_ ? earlier_.evaluations + adaptive_->evaluations() : 0;
}

std::int64_t Stepping::rejected() const {
  return adaptive_ ? earlier_.rejected + adaptive_->rejected(current_.step - earlier_.start_step)
                   : 0;
}

}  // namespace sim
