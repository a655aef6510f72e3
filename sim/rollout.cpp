#include "sim/rollout.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>

#include "sim/adaptive.hpp"
#include "sim/contact_model.hpp"
#include "sim/initial.hpp"
#include "sim/integrator.hpp"
#include "sim/step.hpp"

namespace sim {
namespace {

// The watchdog looks about once per simulated millisecond (every step when adaptive).
constexpr double kEnergyCheckPeriod = 1e-3;  // s

// The first quantity of the state that is NaN or infinite, or null when all are finite.
const char* nonFinite(const State& s) {
  if (!s.x_world.allFinite()) return "the position of the centre of mass";
  if (!s.v_world.allFinite()) return "the velocity of the centre of mass";
  if (!s.q.coeffs().allFinite()) return "the orientation";
  if (!s.L_world.allFinite()) return "the angular momentum";
  return nullptr;
}

std::string stepAdvice(const Model& model) {
  const IntegratorTraits traits = integratorTraits(model.integrator);
  if (!traits.advice_on_stop.empty()) return std::string(traits.advice_on_stop);
  if (isAdaptive(model.integrator)) return "try a smaller simulation.tolerance";
  return "try a smaller simulation.dt";
}

}  // namespace

Rollout::Rollout(Model model) : Rollout(model, initialState(model)) {}

Rollout::Rollout(Model model, const State& start)
    : model_(std::move(model)),
      active_(model_),
      previous_(start),
      current_(start),
      watchdog_(0, 0, false, "") {
  if (contactTraits(model_.contact.model).switches) {
    auto_.emplace(model_);
    active_ = auto_->start(current_);
    previous_ = current_;
  }
  if (isAdaptive(model_.integrator))
    adaptive_ = std::make_unique<AdaptiveStepper>(active_, current_);
  summary_.first = summary_.last = telemetryOf(active_, current_);
  spin_ = summary_.first.spin;
  summary_.max_tilt_deg = summary_.first.tilt_deg;
  min_cos_tilt_ = std::cos(summary_.first.tilt_deg * M_PI / 180.0);
  // Reversals of the spin n = ω·ẑ at the start (opposite to initial.spin when upside down).
  reversals_ = ReversalDetector(summary_.first.spin);
  watchdog_ = Watchdog(start.t, summary_.first.energy,
                       summary_.first.contacts == 0 || summary_.first.normal_force <= 0,
                       stepAdvice(model_));
  // The start is watched too: a body started on the rim of its top under rolling (a tilt of
  // 89°) was stopped a step later for a rise of energy, or a NaN, with the advice of a smaller
  // step, which cannot help.
  if (stopsOnRim()) {
    const Eigen::Matrix3d R = current_.q.normalized().toRotationMatrix();
    watch(R, angularVelocity(*model_.body, R, current_.L_world));
  }
}

Rollout::Rollout(const Rollout& other)
    : model_(other.model_),
      active_(other.active_),
      previous_(other.previous_),
      current_(other.current_),
      last_step_(other.last_step_),
      adaptive_(other.adaptive_ ? std::make_unique<AdaptiveStepper>(*other.adaptive_) : nullptr),
      earlier_(other.earlier_),
      auto_(other.auto_),
      summary_(other.summary_),
      last_due_s_(other.last_due_s_),
      reversals_(other.reversals_),
      spin_(other.spin_),
      min_cos_tilt_(other.min_cos_tilt_),
      watchdog_(other.watchdog_) {}

Rollout::Rollout(Rollout&&) noexcept = default;
Rollout& Rollout::operator=(Rollout&&) noexcept = default;
Rollout::~Rollout() = default;

bool Rollout::advanceTo(double t) {
  return advance(t, false);
}

bool Rollout::advanceToReversal(double t) {
  return advance(t, true);
}

bool Rollout::advance(double t, bool until_reversal) {
  // Sampled faster than it steps (10 kHz against rk4's 2 kHz), most calls take no step: they
  // read no clock and count nothing (two clock reads and an acos a call were a fifth of a
  // 10 kHz run; docs/speed.md "Simulation: speed against error"); nor per step when stepping to
  // a reversal (they were 6 % of a sweep's runs stepped one by one).
  const std::size_t reversals = summary_.reversals.size();
  if (!stopped() && current_.t < t && !sameTime(current_.t, t)) {
    const auto start = std::chrono::steady_clock::now();
    while (!stopped() && current_.t < t && !sameTime(current_.t, t)) {
      if (stop_.stop_requested() || external_.stop_requested()) {
        summary_.stop_requested = true;
        break;
      }
      stepOnce();
      if (until_reversal && summary_.reversals.size() > reversals) break;
    }
    summary_.wall_s +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    countSteps();
  }
  const bool reached = !stopped() || current_.t >= t || sameTime(current_.t, t);
  last_due_s_ = std::min(t, current_.t);
  return reached;
}

bool Rollout::advanceOneStep() {
  if (!stopped() && (stop_.stop_requested() || external_.stop_requested()))
    summary_.stop_requested = true;
  if (stopped()) return false;
  const auto start = std::chrono::steady_clock::now();
  stepOnce();
  summary_.wall_s +=
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  countSteps();
  last_due_s_ = current_.t;
  return true;
}

void Rollout::setState(State s) {
  s.t = current_.t;
  s.step = current_.step;
  s.q.normalize();
  if (auto_) {  // chosen again as at the start: rolling where it holds, else sliding
    const ContactModel before = active_.contact.model;
    auto_.emplace(model_);
    active_ = auto_->start(s);
    if (active_.contact.model != before) {
      ++summary_.switches;
      summary_.mode_changes.push_back({s.t, active_.contact.model});
    }
  } else {
    holdOnFloor(active_, s);
  }
  previous_ = current_ = s;
  last_step_.stepTaken();  // a step of no length: its ends are s
  if (adaptive_) restartStepper();
  const Telemetry now = telemetryOf(active_, current_);
  spin_ = now.spin;
  watchdog_.restartEnergy(now.energy);
  last_due_s_ = current_.t;
}

void Rollout::restartStepper() {
  earlier_.evaluations += adaptive_->evaluations();
  earlier_.rejected += adaptive_->rejected(current_.step - earlier_.start_step);
  adaptive_ = std::make_unique<AdaptiveStepper>(active_, current_);
  earlier_.start_step = current_.step;
  last_step_.denseLost();  // the new stepper has no dense output for the step just ended
}

void Rollout::stepOnce() {
  if (auto_)
    if (std::optional<ModeChange> back = auto_->handBack()) changeMode(std::move(*back));
  const double previous_spin = spin_;
  previous_ = current_;
  const bool sliding = auto_ && AutoSwitch::sliding(active_);
  if (adaptive_) {
    current_ = adaptive_->step(current_.step + 1);
    // The integrator's own copy is not touched: the rates use q normalised. (Under rolling
    // the stepper integrates no z or v; its states come on the constraint.)
    current_.q.normalize();
    if (sliding) auto_->countStuck(active_, current_, current_.t - previous_.t);
  } else if (sliding) {
    // Auto sliding: the smooth contact in steps of its own up to the step's end.
    const std::int64_t index = current_.step + 1;
    auto_->advance(active_, current_, static_cast<double>(index) * model_.dt);
    current_.step = index;
    current_.t = static_cast<double>(index) * model_.dt;
  } else {
    step(active_, current_);  // which puts a rolling state back on the constraint itself
  }
  last_step_.stepTaken();
  if (auto_) switchModes();
  // The tilt's cosine is R(2,2) = (w² + z² − x² − y²)/|q|² of the orientation quaternion.
  const Eigen::Quaterniond& q = current_.q;
  min_cos_tilt_ =
      std::min(min_cos_tilt_,
               (q.w() * q.w() + q.z() * q.z() - q.x() * q.x() - q.y() * q.y()) / q.squaredNorm());
  // The step end's rotation and ω, once for the spin and the watchdog.
  const Eigen::Matrix3d R = current_.q.normalized().toRotationMatrix();
  const Eigen::Vector3d w = angularVelocity(*model_.body, R, current_.L_world);
  spin_ = w.z();
  locateReversal(previous_spin, spin_);
  if (current_.step % checkEvery() == 0) watch(R, w);
}

bool Rollout::stopsOnRim() const {
  const ContactTraits traits = contactTraits(model_.contact.model);
  return traits.stops_on_rim ||
         (model_.body->surface.kind == Surface::Kind::Mesh && traits.touch != Touch::Grid);
}

void Rollout::watch(const Eigen::Matrix3d& R, const Eigen::Vector3d& w) {
  StepEnd end;
  end.t = current_.t;
  end.step = current_.step;
  end.non_finite = nonFinite(current_);
  if (!end.non_finite) {
    const EndReading reading = readEnd(active_, current_, w);
    end.energy = reading.energy_J;
    end.contacts = reading.contacts;
    if (stopsOnRim() && model_.body->surface.lowestOnRim(-R.row(2).transpose())) {
      end.rim_tilt_deg = std::acos(std::clamp(R(2, 2), -1.0, 1.0)) * 180.0 / M_PI;
      if (model_.body->surface.kind == Surface::Kind::Mesh)
        end.cap_deg = std::atan(model_.body->surface.mesh.fit.cap_slope) * 180.0 / M_PI;
    }
  }
  if (const std::optional<Stop> stop = watchdog_.observe(end)) {
    summary_.stop = stop;
    summary_.divergence = watchdog_.message();
  }
}

// Reversals (sim/reversals.hpp, the rule): n between the step's ends is read on the interpolant
// of the step, so crossings and thresholds are placed as accurately as the states between steps.
void Rollout::locateReversal(double previous_spin, double spin) {
  const bool at_end = current_.t >= model_.duration * (1 - kSameTime);
  reversals_.step(
      previous_.t, previous_spin, current_.t, spin, watchdog_.lastFlight(), at_end, [&](double t) {
        return angularVelocity(model_,
                               last_step_.at(t, active_, previous_, current_, adaptive_.get()))
            .z();
      });
  if (reversals_.reversals().size() > summary_.reversals.size()) {
    summary_.reversals = reversals_.reversals();
    if (!summary_.first_reversal_s) summary_.first_reversal_s = summary_.reversals.front();
  }
}

State Rollout::stateAt(double t) const {
  // A time within rounding of a step is that step's own state (stamped with the time asked).
  for (const State* end : {&current_, &previous_}) {
    if (!sameTime(t, end->t)) continue;
    State s = *end;
    s.t = t;
    return s;
  }
  bool on_constraint = false;
  State s = last_step_.at(t, active_, previous_, current_, adaptive_.get(), &on_constraint);
  if (on_constraint) return s;  // normalised and placed by the stepper (adaptive.cpp's Rolling)
  s.q.normalize();
  holdOnFloor(last_step_.modeAt(t, active_), s);
  return s;
}

Telemetry Rollout::sampleAt(double t) const {
  return telemetryOf(last_step_.modeAt(t, active_), stateAt(t));
}

void Rollout::countSteps() const {
  summary_.steps = current_.step;
  summary_.max_tilt_deg = std::max(summary_.max_tilt_deg,
                                   std::acos(std::clamp(min_cos_tilt_, -1.0, 1.0)) * 180.0 / M_PI);
  if (adaptive_) {
    summary_.evaluations = earlier_.evaluations + adaptive_->evaluations();
    summary_.rejected =
        earlier_.rejected + adaptive_->rejected(current_.step - earlier_.start_step);
  }
}

const RunSummary& Rollout::summary() const {
  countSteps();
  if (last_due_s_) {
    summary_.last = sampleAt(*last_due_s_);
    last_due_s_.reset();
  }
  return summary_;
}

std::int64_t Rollout::checkEvery() const {
  return adaptive_ ? 1 : std::max<std::int64_t>(1, std::llround(kEnergyCheckPeriod / model_.dt));
}

void Rollout::switchModes() {
  std::optional<ModeChange> change =
      auto_->afterStep(active_, previous_, current_, [this](double t) { return stateAt(t); });
  if (change) changeMode(std::move(*change));
}

void Rollout::changeMode(ModeChange change) {
  last_step_.cut(change.t_s, active_, current_);
  active_ = std::move(change.next);
  ++summary_.switches;
  summary_.mode_changes.push_back({change.t_s, active_.contact.model});
  State& s = change.start;
  if (adaptive_) {
    s.t = change.t_s;
    s.step = current_.step;
    current_ = s;
    restartStepper();
  } else if (change.t_s < current_.t) {
    const double t_end = current_.t;
    const std::int64_t index = current_.step;
    auto_->advance(active_, s, t_end);
    s.t = t_end;
    s.step = index;
    current_ = s;
  } else {
    current_ = s;
  }
}

std::vector<double> sampleTimes(double duration, double rate) {
  std::vector<double> times;
  const auto count = static_cast<std::int64_t>(std::floor(duration * rate * (1 + kSameTime)));
  times.reserve(static_cast<std::size_t>(count) + 2);
  for (std::int64_t k = 0; k <= count; ++k) times.push_back(static_cast<double>(k) / rate);
  if (!sameTime(times.back(), duration)) times.push_back(duration);
  return times;
}

}  // namespace sim
