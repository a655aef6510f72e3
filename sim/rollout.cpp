#include "sim/rollout.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>

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

// contact.model auto: its switch, else none.
std::optional<AutoSwitch> autoSwitchOf(const Model& model) {
  if (!contactTraits(model.contact.model).switches) return std::nullopt;
  return AutoSwitch(model);
}

}  // namespace

Rollout::Rollout(Model model) : Rollout(model, initialState(model)) {}

Rollout::Rollout(Model model, State start)
    : model_(std::move(model)),
      auto_(autoSwitchOf(model_)),
      // Under auto the first mode, chosen from the start (which it may put on rolling's
      // constraint).
      active_(auto_ ? auto_->start(start) : model_),
      steps_(active_, start),
      watchdog_(0, 0, false, "") {
  summary_.first = summary_.last = telemetryOf(active_, start);
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
    const Eigen::Matrix3d R = start.q.normalized().toRotationMatrix();
    watch(R, angularVelocity(*model_.body, R, start.L_world));
  }
}

Rollout::Rollout(const Rollout& other)
    : model_(other.model_),
      auto_(other.auto_),
      active_(other.active_),
      steps_(other.steps_),
      summary_(other.summary_),
      last_due_s_(other.last_due_s_),
      reversals_(other.reversals_),
      spin_(other.spin_),
      min_cos_tilt_(other.min_cos_tilt_),
      watchdog_(other.watchdog_),
      land_at_(other.land_at_) {}

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
  const State& now = steps_.current();
  if (!stopped() && now.t < t && !sameTime(now.t, t)) {
    const auto start = std::chrono::steady_clock::now();
    while (!stopped() && now.t < t && !sameTime(now.t, t)) {
      if (stop_.requested()) {
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
  const bool reached = !stopped() || now.t >= t || sameTime(now.t, t);
  last_due_s_ = std::min(t, now.t);
  return reached;
}

bool Rollout::advanceOneStep() {
  if (!stopped() && stop_.requested()) summary_.stop_requested = true;
  if (stopped()) return false;
  const auto start = std::chrono::steady_clock::now();
  stepOnce();
  summary_.wall_s +=
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  countSteps();
  last_due_s_ = steps_.current().t;
  return true;
}

void Rollout::setState(State s) {
  s.t = steps_.current().t;
  s.step = steps_.current().step;
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
  steps_.startFrom(active_, s);
  const Telemetry now = telemetryOf(active_, s);
  spin_ = now.spin;
  watchdog_.restartEnergy(now.energy);
  last_due_s_ = s.t;
}

void Rollout::stepOnce() {
  if (auto_)
    if (std::optional<ModeChange> back = auto_->handBack()) changeMode(std::move(*back));
  const double previous_spin = spin_;
  const bool sliding = auto_ && AutoSwitch::sliding(active_);
  if (sliding && !steps_.adaptive()) {
    // Auto sliding: the smooth contact in steps of its own up to the step's end.
    steps_.stepBy(model_.dt, [this](State& s, double t_end) { auto_->advance(active_, s, t_end); });
  } else {
    steps_.step(active_);
    land();
    const State& b = steps_.current();
    if (sliding) auto_->countStuck(active_, b, b.t - steps_.previous().t);
  }
  if (auto_) switchModes();
  const State& end = steps_.current();
  // The tilt's cosine is R(2,2) = (w² + z² − x² − y²)/|q|² of the orientation quaternion.
  const Eigen::Quaterniond& q = end.q;
  min_cos_tilt_ =
      std::min(min_cos_tilt_,
               (q.w() * q.w() + q.z() * q.z() - q.x() * q.x() - q.y() * q.y()) / q.squaredNorm());
  // The step end's rotation and ω, once for the spin and the watchdog.
  const Eigen::Matrix3d R = end.q.normalized().toRotationMatrix();
  const Eigen::Vector3d w = angularVelocity(*model_.body, R, end.L_world);
  spin_ = w.z();
  locateReversal(previous_spin, spin_);
  if (end.step % checkEvery() == 0) watch(R, w);
}

bool Rollout::landAt(std::optional<double> t) {
  if (t && !steps_.adaptive()) return false;
  land_at_ = t;
  return true;
}

void Rollout::land() {
  if (!land_at_) return;
  const double t = *land_at_;
  const State& end = steps_.current();
  if (end.t < t || sameTime(end.t, t)) return;
  land_at_.reset();
  if (t <= steps_.previous().t) return;
  // The step's state at t, on the constraint, becomes its end; a new stepper goes on from it.
  State s = steps_.stateAt(t, active_);
  s.t = t;
  s.step = end.step;
  steps_.cut(t, active_);
  steps_.endAt(active_, s);
}

bool Rollout::stopsOnRim() const {
  const ContactTraits traits = contactTraits(model_.contact.model);
  return traits.stops_on_rim ||
         (model_.body->surface.kind == Surface::Kind::Mesh && traits.touch != Touch::Grid);
}

void Rollout::watch(const Eigen::Matrix3d& R, const Eigen::Vector3d& w) {
  const State& now = steps_.current();
  StepEnd end;
  end.t = now.t;
  end.step = now.step;
  end.non_finite = nonFinite(now);
  if (!end.non_finite) {
    const EndReading reading = readEnd(active_, now, w);
    end.energy = reading.energy_J;
    end.contacts = reading.contacts;
    if (stopsOnRim() && model_.body->surface.lowestOnRim(-R.row(2).transpose())) {
      end.rim_tilt_deg = std::acos(std::clamp(R(2, 2), -1.0, 1.0)) * 180.0 / M_PI;
      if (model_.body->surface.kind == Surface::Kind::Mesh) {
        const BottomFit& fit = model_.body->surface.mesh.fit;
        end.cap_deg = std::atan(fit.cap_slope) * 180.0 / M_PI;
        end.cap_meets_edge = fit.cap_meets_edge;
      }
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
  const double t_a = steps_.previous().t, t_b = steps_.current().t;
  const bool at_end = t_b >= model_.duration * (1 - kSameTime);
  reversals_.step(t_a, previous_spin, t_b, spin, watchdog_.lastFlight(), at_end,
                  [&](double t) { return steps_.spinAt(t, active_); });
  if (reversals_.reversals().size() > summary_.reversals.size()) {
    summary_.reversals = reversals_.reversals();
    if (!summary_.first_reversal_s) summary_.first_reversal_s = summary_.reversals.front();
  }
}

State Rollout::stateAt(double t) const {
  return steps_.stateAt(t, active_);
}

Telemetry Rollout::sampleAt(double t) const {
  return telemetryOf(steps_.modeAt(t, active_), stateAt(t));
}

void Rollout::countSteps() const {
  summary_.steps = steps_.current().step;
  summary_.max_tilt_deg = std::max(summary_.max_tilt_deg,
                                   std::acos(std::clamp(min_cos_tilt_, -1.0, 1.0)) * 180.0 / M_PI);
  summary_.evaluations = steps_.evaluations();
  summary_.rejected = steps_.rejected();
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
  return steps_.adaptive()
             ? 1
             : std::max<std::int64_t>(1, std::llround(kEnergyCheckPeriod / model_.dt));
}

void Rollout::switchModes() {
  std::optional<ModeChange> change = auto_->afterStep(active_, steps_.previous(), steps_.current(),
                                                      [this](double t) { return stateAt(t); });
  if (change) changeMode(std::move(*change));
}

void Rollout::changeMode(ModeChange change) {
  steps_.cut(change.t_s, active_);
  active_ = std::move(change.next);
  ++summary_.switches;
  summary_.mode_changes.push_back({change.t_s, active_.contact.model});
  const double t_end = steps_.current().t;
  const std::int64_t index = steps_.current().step;
  State& s = change.start;
  if (steps_.adaptive()) {
    s.t = change.t_s;
    s.step = index;
  } else if (change.t_s < t_end) {
    auto_->advance(active_, s, t_end);
    s.t = t_end;
    s.step = index;
  }
  steps_.endAt(active_, s);
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
