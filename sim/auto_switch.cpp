#include "sim/auto_switch.hpp"

#include <algorithm>
#include <cmath>

#include "sim/crossing.hpp"
#include "sim/rolling.hpp"
#include "sim/step.hpp"
#include "sim/switching.hpp"

namespace sim {

Model AutoSwitch::start(State& s) const {
  const Model smooth = modeOf(run_, ContactModel::Smooth, 0);
  const SmoothContactState contact = smoothContactState(smooth, s);
  if (contact.depth <= 0 || contact.slip > run_.contact.slip_velocity) return smooth;
  const Model rolling = modeOf(run_, ContactModel::Rolling, contact.depth);
  State on_rolling = s;
  projectOntoRolling(smooth, on_rolling);
  enforceRolling(rolling, on_rolling);
  if (!rollingMargins(rolling, on_rolling).hold()) return smooth;
  s = on_rolling;
  return rolling;
}

bool AutoSwitch::sliding(const Model& active) {
  return active.contact.model == ContactModel::Smooth;
}

void AutoSwitch::advance(const Model& active, State& s, double t_end) {
  const double span = t_end - s.t;
  if (!sliding(active)) {
    advanceBy(active, s, span);
    return;
  }
  if (!(span > 0)) return;
  const int n = static_cast<int>(std::ceil(span / smoothStep(active) - 1e-9));
  const double h = span / std::max(n, 1);
  for (int i = 0; i < std::max(n, 1); ++i) {
    advanceBy(active, s, h);
    countStuck(active, s, h);
  }
}

void AutoSwitch::countStuck(const Model& smooth, const State& s, double h) {
  const SmoothContactState c = smoothContactState(smooth, s);
  stuck_for_s_ = c.normal > 0 && c.slip < run_.contact.slip_velocity ? stuck_for_s_ + h : 0;
}

std::optional<ModeChange> AutoSwitch::afterStep(const Model& active, const State& a, const State& b,
                                                const StateAt& state_at) {
  if (!sliding(active)) return toSmooth(active, a, b, state_at);
  if (stuck_for_s_ >= kStickTime) tryRolling(active, b);
  return std::nullopt;
}

// Rolling → smooth at the earliest time in the step at which a margin that fails at its end
// reaches zero (at the step's start when it failed there already).
std::optional<ModeChange> AutoSwitch::toSmooth(const Model& rolling, const State& a, const State& b,
                                               const StateAt& state_at) {
  const RollingMargins end = rollingMargins(rolling, b);
  if (end.hold()) return std::nullopt;
  const RollingMargins start = rollingMargins(rolling, a);
  double t_switch = b.t;
  auto locate = [&](double RollingMargins::*margin) {
    if (end.*margin > 0) return;
    if (!(start.*margin > 0)) {
      t_switch = a.t;
      return;
    }
    const double t =
        zeroCrossing([&](double time) { return rollingMargins(rolling, state_at(time)).*margin; },
                     a.t, b.t, start.*margin, end.*margin);
    t_switch = std::min(t_switch, t);
  };
  locate(&RollingMargins::friction);
  locate(&RollingMargins::normal);
  locate(&RollingMargins::rim);
  stuck_for_s_ = 0;
  return ModeChange{t_switch, state_at(t_switch), modeOf(run_, ContactModel::Smooth, 0)};
}

// Smooth → rolling where the slip has stayed below ε: the contact point stopped by a plastic
// impulse, the spring's compression kept as rolling's depth; refused (sliding on) when rolling
// would need nearly all the friction there is.
void AutoSwitch::tryRolling(const Model& smooth, const State& b) {
  const SmoothContactState contact = smoothContactState(smooth, b);
  const Model rolling = modeOf(run_, ContactModel::Rolling, contact.depth);
  State s = b;
  projectOntoRolling(smooth, s);
  enforceRolling(rolling, s);
  const RollingMargins m = rollingMargins(rolling, s);
  if (!(m.normal > 0 && m.rim > 0 &&
        m.friction > (1 - kRollFriction) * rolling.contact.friction * m.normal)) {
    stuck_for_s_ = 0;
    return;
  }
  hand_back_ = ModeChange{b.t, s, rolling};
}

std::optional<ModeChange> AutoSwitch::handBack() {
  std::optional<ModeChange> out = std::move(hand_back_);
  hand_back_.reset();
  return out;
}

}  // namespace sim
