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

namespace sim {
namespace {

constexpr double kReversalFraction = 0.01;
// A sign change of n counts as a reversal only after the body has touched the floor without a
// break for this long: in the air, or bouncing after a drop, n = ω·ẑ swings with the tumbling
// axis and says nothing of the rattleback's spin (a body dropped from 5 cm at 30° bounces for
// about 0.6 s and wobbles through n = 0 several times before it settles).
constexpr double kSettleTime = 0.5;  // s
// …and n must then keep its new sign for this long. A body rocking through tens of degrees
// (after a drop, or tipped far) swings n = ω·ẑ through zero and back within a rocking period
// (the default body: 0.14–0.29 s at 7.0/3.5 Hz, the dips last 20–60 ms); a reversal goes on.
constexpr double kHoldTime = 0.2;  // s

// Nothing in the model adds energy (no drive; friction, dampers and drag only remove it), so a
// rise of the total energy by more than this fraction of its initial value is no integration
// error of a usable step (the bench ladders show ≤ 1e-3 where a step is stable) but the start of
// an instability. Checked about once per simulated millisecond (every step when adaptive).
constexpr double kEnergyGrowthBound = 0.10;
constexpr double kEnergyCheckPeriod = 1e-3;  // s

// Times closer than this (relative) are the same time: a sample asked for at k/rate is the
// step k·dt when the two differ only by rounding.
constexpr double kSameTime = 1e-12;

bool sameTime(double a, double b) { return std::abs(a - b) <= kSameTime * std::max(1.0, std::abs(b)); }

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
  return isAdaptive(model.integrator) ? "try a smaller simulation.tolerance"
                                      : "try a smaller simulation.dt";
}

}  // namespace

Rollout::Rollout(Model model) : Rollout(model, initialState(model)) {}

Rollout::Rollout(Model model, const State& start)
    : model_(std::move(model)), previous_(start), current_(start) {
  if (isAdaptive(model_.integrator)) adaptive_ = std::make_unique<AdaptiveStepper>(model_, start);
  summary_.first = summary_.last = telemetryOf(model_, start);
  spin_ = summary_.first.spin;
  summary_.max_tilt_deg = summary_.first.tilt_deg;
  min_cos_tilt_ = std::cos(summary_.first.tilt_deg * M_PI / 180.0);
  // The sign of the spin n = ω·ẑ at the start (opposite to initial.spin when upside down).
  reference_sign_ = summary_.first.spin == 0 ? 0 : std::copysign(1.0, summary_.first.spin);
  if (summary_.first.contacts == 0 || summary_.first.normal_force <= 0) last_airborne_ = start.t;
  const double e0 = summary_.first.energy;
  energy_bound_ = e0 + kEnergyGrowthBound * std::abs(e0) + 1e-12;
  check_every_ = adaptive_ ? 1 : std::max<std::int64_t>(1, std::llround(kEnergyCheckPeriod / model_.dt));
}

Rollout::Rollout(Rollout&&) noexcept = default;
Rollout& Rollout::operator=(Rollout&&) noexcept = default;
Rollout::~Rollout() = default;

bool Rollout::advanceTo(double t) {
  const auto start = std::chrono::steady_clock::now();
  while (!stopped() && current_.t < t && !sameTime(current_.t, t)) {
    if (stop_.stop_requested() || external_.stop_requested()) {
      summary_.stop_requested = true;
      break;
    }
    stepOnce();
  }
  summary_.wall_s += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  summary_.steps = current_.step;
  summary_.max_tilt_deg =
      std::max(summary_.max_tilt_deg, std::acos(std::clamp(min_cos_tilt_, -1.0, 1.0)) * 180.0 / M_PI);
  if (adaptive_) {
    summary_.evaluations = adaptive_->evaluations();
    summary_.rejected = adaptive_->rejected(current_.step);
  }
  return !stopped() || current_.t >= t || sameTime(current_.t, t);
}

void Rollout::stepOnce() {
  const double previous_spin = spin_;
  previous_ = current_;
  if (adaptive_) {
    current_ = adaptive_->step(current_.step + 1);
    // The integrator's own copy is not touched: under rolling, z and v do not enter the
    // equations (ẋ = −ω × r comes from q and L), and the rates use q normalised, so putting
    // the handed-out state back on the constraint here is the same as restoring it inside.
    current_.q.normalize();
    if (model_.contact.model == ContactModel::Rolling) enforceRolling(model_, current_);
  } else {
    step(model_, current_);  // which puts a rolling state back on the constraint itself
  }
  have_rates_ = false;
  // The tilt's cosine is R(2,2) = (w² + z² − x² − y²)/|q|² of the orientation quaternion.
  const Eigen::Quaterniond& q = current_.q;
  min_cos_tilt_ = std::min(min_cos_tilt_, (q.w() * q.w() + q.z() * q.z() - q.x() * q.x() -
                                           q.y() * q.y()) / q.squaredNorm());
  spin_ = angularVelocity(model_, current_).z();
  locateReversal(previous_spin, spin_);
  if (current_.step % check_every_ == 0) watch();
}

// NaN or infinity, energy from nowhere, or a rolling body on its rim: the run stops, naming
// the quantity, the time and the step.
void Rollout::watch() {
  if (const char* quantity = nonFinite(current_)) {
    std::ostringstream msg;
    msg << quantity << " became NaN or infinite at t = " << current_.t << " s (step "
        << current_.step << "); " << stepAdvice(model_);
    summary_.divergence = msg.str();
    return;
  }
  // The energy, and whether the floor carries the body. Rolling keeps it on the floor and has
  // no spring: its energy needs no contact solve (this check runs every step or millisecond).
  const bool rolling = model_.contact.model == ContactModel::Rolling;
  double energy = 0;
  if (rolling) {
    const Eigen::Vector3d w = angularVelocity(model_, current_);
    const double M = model_.body->mass;
    energy = 0.5 * M * current_.v_world.squaredNorm() + 0.5 * w.dot(current_.L_world) +
             M * model_.gravity * current_.x_world.z();
  } else {
    const Telemetry now = telemetryOf(model_, current_);
    if (now.contacts == 0 || now.normal_force <= 0) last_airborne_ = current_.t;
    energy = now.energy;
  }
  if (!(energy <= energy_bound_)) {
    const double e0 = summary_.first.energy;
    std::ostringstream msg;
    msg << "the energy rose from " << e0 << " J to " << energy << " J (" << std::showpos
        << 100 * (energy - e0) / std::abs(e0) << std::noshowpos << " %, beyond the "
        << 100 * kEnergyGrowthBound << " % that nothing in the model can supply) at t = "
        << current_.t << " s (step " << current_.step << "); " << stepAdvice(model_);
    summary_.divergence = msg.str();
    return;
  }
  // Rolling is a smooth surface rolling on the floor; tipped onto the edge of its flat top the
  // body pivots on an edge, which that model cannot describe.
  if (rolling) {
    const Eigen::Matrix3d R = current_.q.toRotationMatrix();
    if (!model_.body->surface.lowestOnRim(-R.row(2).transpose())) return;
    const double tilt = std::acos(std::clamp(R(2, 2), -1.0, 1.0)) * 180.0 / M_PI;
    std::ostringstream msg;
    msg << "the body tipped onto the edge of its top (tilt " << tilt << " degrees) at t = "
        << current_.t << " s (step " << current_.step
        << "), where rolling on its smooth bottom no longer describes it; use "
           "contact.model smooth or points";
    summary_.divergence = msg.str();
  }
}

// A reversal: n crosses zero against the reference sign and goes on to reach kReversalFraction
// of the initial |n| the other way (a spin that only decays to rest and dithers about zero is
// no reversal). Its time is the crossing, found on the interpolant of the step by regula falsi
// (Illinois), so it is as accurate as the states between steps.
void Rollout::locateReversal(double previous_spin, double spin) {
  if (reference_sign_ == 0 || !std::isfinite(spin)) return;
  const double threshold = kReversalFraction * std::abs(summary_.first.spin);
  // Before n has reached the threshold the other way, the latest crossing is the candidate;
  // after it, the crossing stays, and only n back beyond the threshold the old way undoes it
  // (a wiggle about zero in the middle of a reversal keeps its first crossing).
  if (spin * reference_sign_ < 0 && previous_spin * reference_sign_ >= 0 && !crossing_reached_) {
    crossing_ = zeroCrossing([&](double t) { return angularVelocity(model_, interpolate(t)).z(); },
                             previous_.t, current_.t, previous_spin, spin);
  }
  // A crossing while the body was in the air or still bouncing is none, nor one that n takes
  // back before it has held the new side for kHoldTime.
  if (crossing_ && *crossing_ - last_airborne_ < kSettleTime) crossing_.reset();
  if (crossing_ && crossing_reached_ && spin * reference_sign_ > threshold) crossing_.reset();
  if (crossing_ && spin * reference_sign_ < -threshold) crossing_reached_ = true;
  // At the run's end a crossing that has reached the threshold counts: nothing undid it.
  const bool at_end = current_.t >= model_.duration * (1 - kSameTime);
  if (crossing_ && crossing_reached_ && (current_.t - *crossing_ >= kHoldTime || at_end)) {
    summary_.reversals.push_back(*crossing_);
    if (!summary_.first_reversal_s) summary_.first_reversal_s = *crossing_;
    crossing_.reset();
    reference_sign_ = -reference_sign_;
  }
  if (!crossing_) crossing_reached_ = false;
}

// Between the ends of the last step: the adaptive stepper's dense output, or a cubic Hermite
// interpolant of the whole state with its rates at both ends (x with v, v with v̇, q with q̇,
// L with τ): its error is O(h⁴) for a smooth motion, below the integrators' own, and it hits
// both ends exactly. (Slerp would interpolate the rotation at only O(h²) and ignore ω.)
State Rollout::interpolate(double t) const {
  if (adaptive_) return adaptive_->at(t);
  if (!have_rates_) {
    rates_previous_ = packRates(ratesOf(model_, previous_));
    rates_current_ = packRates(ratesOf(model_, current_));
    have_rates_ = true;
  }
  const double h = current_.t - previous_.t;
  const double u = (t - previous_.t) / h;
  const double h00 = (1 + 2 * u) * (1 - u) * (1 - u), h10 = u * (1 - u) * (1 - u);
  const double h01 = u * u * (3 - 2 * u), h11 = u * u * (u - 1);
  const Vector13 y = h00 * packState(previous_) + h10 * h * rates_previous_ +
                     h01 * packState(current_) + h11 * h * rates_current_;
  State s;
  s.x_world = y.segment<3>(0);
  s.v_world = y.segment<3>(3);
  s.q.coeffs() = y.segment<4>(6);
  s.L_world = y.segment<3>(10);
  s.t = t;
  s.step = previous_.step;
  return s;
}

State Rollout::stateAt(double t) const {
  // A time within rounding of a step is that step's own state (stamped with the time asked).
  for (const State* end : {&current_, &previous_}) {
    if (!sameTime(t, end->t)) continue;
    State s = *end;
    s.t = t;
    return s;
  }
  State s = interpolate(t);
  s.q.normalize();
  if (model_.contact.model == ContactModel::Rolling) enforceRolling(model_, s);
  return s;
}

Telemetry Rollout::sampleAt(double t) {
  summary_.last = telemetryOf(model_, stateAt(t));
  return summary_.last;
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
