#include "sim/rollout.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>

#include "sim/adaptive.hpp"
#include "sim/crossing.hpp"
#include "sim/initial.hpp"
#include "sim/rolling.hpp"
#include "sim/step.hpp"
#include "sim/switching.hpp"

namespace sim {
namespace {

// The watchdog looks about once per simulated millisecond (every step when adaptive).
constexpr double kEnergyCheckPeriod = 1e-3;  // s

// Times closer than this (relative) are the same time: a sample asked for at k/rate is the
// step k·dt when the two differ only by rounding.
constexpr double kSameTime = 1e-12;

bool sameTime(double a, double b) {
  return std::abs(a - b) <= kSameTime * std::max(1.0, std::abs(b));
}

using Vector13 = Eigen::Matrix<double, 13, 1>;

Vector13 packState(const State& s) {
  Vector13 y;
  y << s.x_world, s.v_world, s.q.coeffs(), s.L_world;
  return y;
}

Vector13 packRates(const Rates& r) {
  Vector13 y;
  y << r.dx, r.dv, r.dq, r.dL;
  return y;
}

// The first quantity of the state that is NaN or infinite, or null when all are finite.
const char* nonFinite(const State& s) {
  if (!s.x_world.allFinite()) return "the position of the centre of mass";
  if (!s.v_world.allFinite()) return "the velocity of the centre of mass";
  if (!s.q.coeffs().allFinite()) return "the orientation";
  if (!s.L_world.allFinite()) return "the angular momentum";
  return nullptr;
}

std::string stepAdvice(const Model& model) {
  if (isAdaptive(model.integrator)) return "try a smaller simulation.tolerance";
  // Forward Euler adds energy to every rotation at every step: a smaller step only delays the
  // stop (Kane & Levinson under rolling stopped at every step from 4 ms to 62.5 µs, the time
  // doubling a halving: a physicist's trial), which the seed's scenes, on a damped floor, hide.
  if (model.integrator == Integrator::Euler)
    return "forward Euler adds energy at every step, which a smaller simulation.dt only "
           "delays: use simulation.integrator rk4 (or symplectic off rolling)";
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
  if (model_.contact.model == ContactModel::Auto) startAuto();
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
  check_every_ =
      adaptive_ ? 1 : std::max<std::int64_t>(1, std::llround(kEnergyCheckPeriod / model_.dt));
  // The start is watched too: a body started on the rim of its top under rolling (a tilt of
  // 89°) was stopped a step later for a rise of energy, or a NaN, with the advice of a smaller
  // step, which cannot help.
  if (model_.contact.model == ContactModel::Rolling) {
    const Eigen::Matrix3d R = current_.q.normalized().toRotationMatrix();
    watch(R, angularVelocity(*model_.body, R, current_.L_world));
  }
}

Rollout::Rollout(Rollout&&) noexcept = default;
Rollout& Rollout::operator=(Rollout&&) noexcept = default;
Rollout::~Rollout() = default;

bool Rollout::advanceTo(double t) {
  // Sampled faster than it steps (10 kHz against rk4's 2 kHz), most calls take no step: they
  // read no clock and count nothing (two clock reads and an acos a call were a fifth of a
  // 10 kHz run; docs/speed.md "Writing beside the run (2026-11-27, eleventh session; issue 27)").
  if (!stopped() && current_.t < t && !sameTime(current_.t, t)) {
    const auto start = std::chrono::steady_clock::now();
    while (!stopped() && current_.t < t && !sameTime(current_.t, t)) {
      if (stop_.stop_requested() || external_.stop_requested()) {
        summary_.stop_requested = true;
        break;
      }
      stepOnce();
    }
    summary_.wall_s +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    countSteps();
  }
  const bool reached = !stopped() || current_.t >= t || sameTime(current_.t, t);
  reached_ = reached ? std::min(t, current_.t) : current_.t;
  last_filled_ = false;
  return reached;
}

void Rollout::stepOnce() {
  if (hand_back_) {
    changeMode(hand_back_->start, current_.t, hand_back_->rolling);
    hand_back_.reset();
  }
  const double previous_spin = spin_;
  previous_ = current_;
  if (adaptive_) {
    current_ = adaptive_->step(current_.step + 1);
    // The integrator's own copy is not touched: the rates use q normalised. (Under rolling
    // the stepper integrates no z or v; its states come on the constraint.)
    current_.q.normalize();
    if (active_.contact.model != model_.contact.model &&
        active_.contact.model == ContactModel::Smooth)
      countStuck(current_, current_.t - previous_.t);
  } else if (active_.contact.model != model_.contact.model &&
             active_.contact.model == ContactModel::Smooth) {
    // Auto sliding: the smooth contact in steps of its own up to the step's end.
    const std::int64_t index = current_.step + 1;
    advanceSmooth(current_, static_cast<double>(index) * model_.dt);
    current_.step = index;
    current_.t = static_cast<double>(index) * model_.dt;
  } else {
    step(active_, current_);  // which puts a rolling state back on the constraint itself
  }
  have_rates_ = false;
  hermite_ = false;
  if (model_.contact.model == ContactModel::Auto) switchModes();
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
  if (current_.step % check_every_ == 0) watch(R, w);
}

void Rollout::watch(const Eigen::Matrix3d& R, const Eigen::Vector3d& w) {
  StepEnd end{current_.t, current_.step, nonFinite(current_)};
  if (!end.non_finite) {
    // Rolling keeps the body on the floor and has no spring: its energy needs no contact solve
    // (this runs every step or millisecond).
    if (active_.contact.model == ContactModel::Rolling) {
      const double M = active_.body->mass, depth = active_.rolling_depth;
      end.energy = 0.5 * M * current_.v_world.squaredNorm() + 0.5 * w.dot(current_.L_world) +
                   M * active_.gravity * current_.x_world.z() +
                   (depth > 0 ? 0.5 * active_.contact.stiffness * depth * depth : 0.0);
    } else {
      const Telemetry now = telemetryOf(active_, current_);
      end.energy = now.energy;
      end.contacts = now.contacts;
    }
    if (model_.contact.model == ContactModel::Rolling) {
      if (model_.body->surface.lowestOnRim(-R.row(2).transpose()))
        end.rim_tilt_deg = std::acos(std::clamp(R(2, 2), -1.0, 1.0)) * 180.0 / M_PI;
    }
  }
  if (const std::optional<Stop> stop = watchdog_.observe(end)) {
    summary_.stop = stop;
    summary_.divergence = watchdog_.message();
  }
}

// Reversals (sim/reversals.hpp, the rule): each crossing's time is found on the interpolant of
// the step by regula falsi (Illinois), so it is as accurate as the states between steps.
void Rollout::locateReversal(double previous_spin, double spin) {
  const bool at_end = current_.t >= model_.duration * (1 - kSameTime);
  reversals_.step(
      previous_.t, previous_spin, current_.t, spin, watchdog_.lastFlight(), at_end, [&] {
        return zeroCrossing([&](double t) { return angularVelocity(model_, interpolate(t)).z(); },
                            previous_.t, current_.t, previous_spin, spin);
      });
  if (reversals_.reversals().size() > summary_.reversals.size()) {
    summary_.reversals = reversals_.reversals();
    if (!summary_.first_reversal_s) summary_.first_reversal_s = summary_.reversals.front();
  }
}

// Between the ends of the last step: the adaptive stepper's dense output, or a cubic Hermite
// interpolant of the whole state with its rates at both ends (x with v, v with v̇, q with q̇,
// L with τ): its error is O(h⁴) for a smooth motion, below the integrators' own, and it hits
// both ends exactly. (Slerp would interpolate the rotation at only O(h²) and ignore ω.)
State Rollout::interpolate(double t, bool* on_constraint) const {
  if (on_constraint) *on_constraint = false;
  // Before a switch inside the last step: the old mode's own step, from its start to where it
  // ended before the switch cut it (issue 26: interpolating across the switch, a rolling state
  // to a sliding one, made the samples' energy dip and recover).
  if (previous_.t < switched_at_ && t < switched_at_ && !sameTime(t, switched_at_))
    return hermite(previous_, packRates(ratesOf(before_switch_, previous_)), before_end_,
                   packRates(ratesOf(before_switch_, before_end_)), t);
  if (adaptive_ && !hermite_) {
    if (on_constraint) *on_constraint = adaptive_->keepsRolling();
    return adaptive_->at(t);
  }
  if (!have_rates_) {
    rates_previous_ = packRates(ratesOf(active_, previous_));
    rates_current_ = packRates(ratesOf(active_, current_));
    have_rates_ = true;
  }
  return hermite(previous_, rates_previous_, current_, rates_current_, t);
}

State Rollout::hermite(const State& a, const Vector13& rates_a, const State& b,
                       const Vector13& rates_b, double t) const {
  const double h = b.t - a.t;
  const double u = (t - a.t) / h;
  const double h00 = (1 + 2 * u) * (1 - u) * (1 - u), h10 = u * (1 - u) * (1 - u);
  const double h01 = u * u * (3 - 2 * u), h11 = u * u * (u - 1);
  const Vector13 y =
      h00 * packState(a) + h10 * h * rates_a + h01 * packState(b) + h11 * h * rates_b;
  State s;
  s.x_world = y.segment<3>(0);
  s.v_world = y.segment<3>(3);
  s.q.coeffs() = y.segment<4>(6);
  s.L_world = y.segment<3>(10);
  s.t = t;
  s.step = a.step;
  return s;
}

const Model& Rollout::modeAt(double t) const {
  return t < switched_at_ && !sameTime(t, switched_at_) ? before_switch_ : active_;
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
  State s = interpolate(t, &on_constraint);
  if (on_constraint) return s;  // normalised and placed by the stepper (adaptive.cpp's Rolling)
  s.q.normalize();
  const Model& mode = modeAt(t);
  if (mode.contact.model == ContactModel::Rolling) enforceRolling(mode, s);
  return s;
}

Telemetry Rollout::sampleAt(double t) const {
  return telemetryOf(modeAt(t), stateAt(t));
}

void Rollout::countSteps() const {
  summary_.steps = current_.step;
  summary_.max_tilt_deg = std::max(summary_.max_tilt_deg,
                                   std::acos(std::clamp(min_cos_tilt_, -1.0, 1.0)) * 180.0 / M_PI);
  if (adaptive_) {
    summary_.evaluations = evaluations_before_ + adaptive_->evaluations();
    summary_.rejected = rejected_before_ + adaptive_->rejected(current_.step - stepper_start_);
  }
}

const RunSummary& Rollout::summary() const {
  countSteps();
  if (!last_filled_) {
    summary_.last = sampleAt(reached_);
    last_filled_ = true;
  }
  return summary_;
}

// Auto's first mode: rolling when the run starts on the floor and rolling holds there, with
// the spring's compression at the start as its depth (at rest M g / k); else sliding.
void Rollout::startAuto() {
  const Model smooth = modeOf(model_, ContactModel::Smooth, 0);
  const SmoothContactState contact = smoothContactState(smooth, current_);
  active_ = smooth;
  if (contact.depth <= 0 || contact.slip > model_.contact.slip_velocity) return;
  const Model rolling = modeOf(model_, ContactModel::Rolling, contact.depth);
  State s = current_;
  projectOntoRolling(smooth, s);
  enforceRolling(rolling, s);
  if (!rollingMargins(rolling, s).hold()) return;
  active_ = rolling;
  previous_ = current_ = s;
}

// The smooth contact from s to `t_end` in equal steps no longer than smoothStep, keeping
// count of how long the contact point has stuck (slip below ε with the spring pressing).
void Rollout::advanceSmooth(State& s, double t_end) {
  const double span = t_end - s.t;
  if (!(span > 0)) return;
  const int n = static_cast<int>(std::ceil(span / smoothStep(active_) - 1e-9));
  const double h = span / std::max(n, 1);
  for (int i = 0; i < std::max(n, 1); ++i) {
    advanceBy(active_, s, h);
    countStuck(s, h);
  }
}

// Auto sliding: how long the contact point has stuck (slip below ε, the spring pressing).
void Rollout::countStuck(const State& s, double h) {
  const SmoothContactState c = smoothContactState(active_, s);
  stuck_for_ = c.normal > 0 && c.slip < model_.contact.slip_velocity ? stuck_for_ + h : 0;
}

// Auto: after each step, whether the other model takes over, and from when.
void Rollout::switchModes() {
  if (active_.contact.model == ContactModel::Rolling) {
    const RollingMargins end = rollingMargins(active_, current_);
    if (end.hold()) return;
    // The earliest time in the step at which a margin that fails at its end reaches zero.
    const RollingMargins start = rollingMargins(active_, previous_);
    double t_switch = current_.t;
    auto locate = [&](double RollingMargins::*margin) {
      if (end.*margin > 0) return;
      if (!(start.*margin > 0)) {
        t_switch = previous_.t;
        return;
      }
      const double t =
          zeroCrossing([&](double time) { return rollingMargins(active_, stateAt(time)).*margin; },
                       previous_.t, current_.t, start.*margin, end.*margin);
      t_switch = std::min(t_switch, t);
    };
    locate(&RollingMargins::friction);
    locate(&RollingMargins::normal);
    locate(&RollingMargins::rim);
    State s = stateAt(t_switch);
    stuck_for_ = 0;
    changeMode(s, t_switch, modeOf(model_, ContactModel::Smooth, 0));
    return;
  }
  if (stuck_for_ < kStickTime) return;
  // Rolling resumes where the slip has stayed below ε: the contact point stopped by a plastic
  // impulse, the spring's compression kept as rolling's depth.
  const SmoothContactState contact = smoothContactState(active_, current_);
  const Model rolling = modeOf(model_, ContactModel::Rolling, contact.depth);
  State s = current_;
  projectOntoRolling(active_, s);
  enforceRolling(rolling, s);
  const RollingMargins m = rollingMargins(rolling, s);
  if (!(m.normal > 0 && m.rim > 0 &&
        m.friction > (1 - kRollFriction) * rolling.contact.friction * m.normal)) {
    stuck_for_ = 0;  // rolling would need nearly all the friction there is: slide on
    return;
  }
  hand_back_ = HandBack{rolling, s};  // at the start of the next step (stepOnce)
}

// Carries out a switch found in the last step at t_switch, from state s (already in the new
// mode's terms): fixed steps finish the step in the new mode; adaptive ones restart there.
void Rollout::changeMode(State s, double t_switch, Model next) {
  before_switch_ = active_;
  before_end_ = current_;
  active_ = std::move(next);
  switched_at_ = t_switch;
  ++summary_.switches;
  summary_.mode_changes.push_back({t_switch, active_.contact.model});
  if (adaptive_) {
    evaluations_before_ += adaptive_->evaluations();
    rejected_before_ += adaptive_->rejected(current_.step - stepper_start_);
    s.t = t_switch;
    s.step = current_.step;
    current_ = s;
    adaptive_ = std::make_unique<AdaptiveStepper>(active_, current_);
    stepper_start_ = current_.step;
    hermite_ = true;  // the new stepper has no dense output for the step just ended
  } else if (t_switch < current_.t) {
    const double t_end = current_.t;
    const std::int64_t index = current_.step;
    if (active_.contact.model == ContactModel::Smooth) {
      advanceSmooth(s, t_end);
    } else {
      advanceBy(active_, s, t_end - t_switch);
    }
    s.t = t_end;
    s.step = index;
    current_ = s;
  } else {
    current_ = s;
  }
  have_rates_ = false;
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
