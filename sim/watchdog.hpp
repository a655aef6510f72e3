// The run's watchdog (docs/physics.md P6) as a unit of its own: fed what the end of each checked
// step holds, it says when a run must stop (a quantity NaN or infinite, energy from nowhere, a
// rolling body on the rim of its top), with the message that says why and what to do, and it
// keeps the time of the last flight (the floor carrying nothing for kFlightTime or more) for the
// reversal rule. A Rollout feeds it; tests feed it scripted values directly.
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

#include "util/names.hpp"

namespace sim {

/// Why a run stopped by itself (RunSummary::stop).
enum class StopReason {
  NonFinite,   ///< a quantity became NaN or infinite
  EnergyGain,  ///< the energy rose beyond what the model can supply
  OnRim,       ///< a rolling body tipped onto the edge of its flat top
};

/// A run that stopped by itself: why, when, and the message that says it.
struct Stop {
  StopReason reason;
  double t = 0;           ///< s
  std::int64_t step = 0;  ///< the step it stopped at
};

/// What the watchdog looks at in the state at the end of a step.
struct StepEnd {
  double t = 0;  ///< s
  std::int64_t step = 0;
  const char* non_finite = nullptr;  ///< the first quantity that is NaN or infinite, if any
  double energy = 0;                 ///< J, the total
  /// Points of the body below the floor; none under rolling, which keeps it on the floor.
  std::optional<int> contacts;
  /// Rolling: the tilt, degrees, when the lowest point lies on the rim of the flat top.
  std::optional<double> rim_tilt_deg;
  /// Where the rim is the edge of a mesh's fitted bottom (docs/physics.md §P11.4): the largest
  /// tilt it holds, degrees.
  std::optional<double> cap_deg;
  bool cap_meets_edge = false;  ///< that tilt is where the bottom itself ends (BottomFit)
};

class Watchdog {
 public:
  /// "In the air" means a flight: the floor carrying nothing for at least this long, s. Contact
  /// lost for a few milliseconds (a hop of a few µm when auto starts to slide with its spring
  /// pushing M g where rolling needed less, or chatter of a skidding body) is no flight; the
  /// bounces after a drop from 5 cm last tens of milliseconds.
  static constexpr double kFlightTime = 0.01;
  /// Nothing in the model adds energy (no drive; friction, dampers and drag only remove it), so
  /// a rise of the total energy by more than this fraction of its initial value is no
  /// integration error of a usable step (the bench ladders show ≤ 1e-3 where a step is stable)
  /// but the start of an instability.
  static constexpr double kEnergyGrowthBound = 0.10;

  /// A run starting at t0 with energy e0 J, in the air at the start or not; `advice` ends the
  /// messages of the stops a smaller step can cure ("try a smaller simulation.dt").
  Watchdog(double t0, double e0, bool in_air_at_start, std::string advice);

  /// Measures energy from nowhere from e0 J on: the caller changed the state (a tap adds energy
  /// that no step did). The last flight is kept.
  void restartEnergy(double e0);

  /// Looks at one step's end: the stop, when the run must stop there (then message() says it).
  std::optional<Stop> observe(const StepEnd& end);

  /// Names the quantity, the time, the step and the way out; empty until a stop.
  const std::string& message() const { return message_; }
  /// The last time the body was in the air (a flight), s; −∞ when never.
  double lastFlight() const { return last_flight_; }

 private:
  double t0_, e0_, bound_;
  std::string advice_, message_;
  double last_flight_ = -std::numeric_limits<double>::infinity();
  double in_air_since_ = std::numeric_limits<double>::quiet_NaN();  ///< NaN: on the floor
};

}  // namespace sim

namespace rb {
template <>
struct NameTable<sim::StopReason> {
  static constexpr std::array<std::pair<sim::StopReason, std::string_view>, 3> entries{{
      {sim::StopReason::NonFinite, "non_finite"},
      {sim::StopReason::EnergyGain, "energy_gain"},
      {sim::StopReason::OnRim, "on_rim"},
  }};
};
}  // namespace rb
